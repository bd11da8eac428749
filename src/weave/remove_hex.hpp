#pragma once
// Taking a hex off the weave: the inverse of gluing it on. What the 1996
// report's triple-doublet deletion does to both hexes of the doublet
// (rules/report/triple_doublet_deletion.rule calls it).
#include "src/stc/stc.hpp"

namespace loom::weave {

/// Removes `hex` from the STC. A face it was glued onto (hex on the face's
/// cell[0], a boundary quad or a face another hex made) is a front face again.
/// A face it made (hex on cell[1]) goes when nothing is glued onto it, and
/// otherwise turns round (node cycle reversed, the other hex on cell[1]) to be
/// a front face of the hex glued there. Then the edges, nodes, chords and
/// sheets nothing uses any more go. A chord or sheet the hex split keeps one
/// id for both parts, as after any removal in a rule. Throws
/// std::runtime_error, before changing anything, when the hex lies on both
/// sides of one face (a knife of its own).
void remove_hex(stc::Stc& stc, stc::Id hex);

}  // namespace loom::weave
