#pragma once
// Gmsh is a process-wide singleton that prints to the terminal, reports errors
// by exceptions of unspecified type or only through its log, and crashes on some
// malformed files. This helper contains all of that: each call runs in a forked
// child process that initialises Gmsh once (silent, no user config files), so a
// crash or a stray message cannot reach Loom, and every failure becomes one
// InputError line.
#include <functional>
#include <string>

namespace loom {

/// Runs `work` (which may call the gmsh:: API) in a child process and returns
/// the bytes it produced. A Gmsh error becomes InputError "WHERE: Gmsh: MESSAGE;
/// HINT"; a crash of the child becomes InputError saying Gmsh crashed; an
/// InputError thrown by `work` is passed on with its message.
std::string run_gmsh_isolated(const std::string& where, const std::string& hint,
                              const std::function<std::string()>& work);

}  // namespace loom
