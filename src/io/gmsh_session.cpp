#include "src/io/gmsh_session.hpp"

#include <fcntl.h>
#include <gmsh.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

// Messages from the child start with one of these bytes.
constexpr char result_ok = 'R', result_gmsh_error = 'G', result_input_error = 'I';

std::string one_line(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  if (message.starts_with("Error: ")) message.erase(0, 7);
  return printable(message);
}

// Some Gmsh readers log an error and return without throwing.
std::string first_logged_error() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (const auto& line : log)
    if (line.starts_with("Error")) return line;
  return {};
}

// In the child: run Gmsh and encode the outcome.
std::string child_outcome(const std::function<std::string()>& work) {
  std::string error;
  try {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::logger::start();
    std::string result = work();
    error = first_logged_error();
    if (error.empty()) return result_ok + result;
  } catch (const InputError& e) {
    return result_input_error + std::string(e.what());
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    gmsh::logger::getLastError(error);
  }
  if (error.empty()) error = first_logged_error();
  if (error.empty()) error = "unknown error";
  return result_gmsh_error + error;
}

[[noreturn]] void run_child(int write_end, const std::function<std::string()>& work) {
  int null_fd = ::open("/dev/null", O_WRONLY);
  if (null_fd >= 0) {
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(null_fd, STDERR_FILENO);
  }
  std::string outcome = child_outcome(work);
  for (std::size_t done = 0; done < outcome.size();) {
    ssize_t n = ::write(write_end, outcome.data() + done, outcome.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  // _exit: no atexit handlers, no flushing of stdio buffers inherited from the parent.
  ::_exit(0);
}

}  // namespace

std::string run_gmsh_isolated(const std::string& where, const std::string& hint,
                              const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  }
  if (child == 0) {
    ::close(fds[0]);
    run_child(fds[1], work);
  }
  ::close(fds[1]);
  std::string outcome;
  char buffer[1 << 16];
  while (true) {
    ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    outcome.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    fail_input(
        where,
        fmt::format("Gmsh crashed while reading the file (signal {}); it is probably malformed", WTERMSIG(status)),
        hint);
  if (outcome.empty()) fail_input(where, "Gmsh stopped without a result", hint);
  std::string payload = outcome.substr(1);
  switch (outcome.front()) {
    case result_ok:
      return payload;
    case result_input_error:
      throw InputError(payload);
    default:
      fail_input(where, "Gmsh: " + one_line(payload), hint);
  }
}

}  // namespace loom
