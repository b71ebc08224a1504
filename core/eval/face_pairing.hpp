// Multi-face tracks scored against a truth, face by face. `clm3d track --faces` numbers faces in
// the order it finds them, a two-face truth (`clm3d synth --photo A --beside B`) in the order they
// were made: the numbers need not agree. Each truth face is paired with the tracked face whose
// points are nearest it over the frames both have; the pair is then scored as any single-face
// sequence. Identity switches (the tracked id nearest a truth face changing from one frame to the
// next) say whether the tracker kept its ids. A table without a face column is one face.
#pragma once

#include <string>
#include <vector>

#include "core/scheme/scheme.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

// A table's rows by face: one table per distinct `face` cell, in order of first appearance, each
// without the face column (its other extra columns kept). A table without a face column is
// returned whole, as one face named "".
struct FaceTable {
  std::string face;
  TrackTable table;
};
std::vector<FaceTable> splitFaces(const TrackTable& table);

// How one truth face was paired: what `clm3d eval` prints per face.
struct FacePairing {
  std::string truthFace;
  std::string trackedFace;  // "" for a table without a face column
  bool paired = false;      // false: no tracked face came near this truth face
  int sharedFrames = 0;     // frames where both have points and the tracked row succeeded
  // Frames (among the truth face's, after the first such frame) where the tracked succeeded row
  // nearest this truth face (within one eye distance) has another id than in the frame before.
  int idSwitches = 0;
};

struct FacePair {
  FacePairing pairing;
  TrackTable truth;    // the truth face's rows
  TrackTable tracked;  // the tracked face's rows (no rows when unpaired)
};

// Whether the table has a `face` column (clm3d track --faces, a two-face truth).
bool hasFaceColumn(const TrackTable& table);

// Pairs every truth face with at most one tracked face, nearest first (mean point distance over
// the eye distance of the truth, over shared frames where the tracked row succeeded; a pair whose
// mean is above one eye distance is no pair). `scheme` gives the eye pair. InputError naming
// `trackedName` when the tables' landmark counts differ.
std::vector<FacePair> pairFaces(const TrackTable& truth, const TrackTable& tracked,
                                const Scheme& scheme, const std::string& trackedName);

}  // namespace clm3d
