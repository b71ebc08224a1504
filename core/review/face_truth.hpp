// Several faces of one video in one tracks CSV (a `face` column, as `clm3d track --faces` writes
// it): split into one per-frame table per face, so that each face is reviewed and corrected as a
// single face is, and joined back into one table the way the command writes it (rows by frame,
// then by face). The studio's Track page keeps one FaceTruth per face; nothing here keeps a
// reference to its arguments.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/track/ground_truth.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

struct FaceTruth {
  int face = 0;               // the id in the face column
  GroundTruthSet truth;       // row i = frame i; frames the face has no row in have no points
  std::vector<bool> present;  // per frame: the table had a row of this face there
};

// `table`'s faces, by id: each face's rows as groundTruthFromTable reads them (keyframes from a
// keyframe column), padded to frameCount. A table without a face column is one face, id 0.
// InputError naming `source` for a face cell that is not a whole number from 0, or a frame at or
// beyond frameCount.
std::vector<FaceTruth> splitFaceTruth(const TrackTable& table, int frameCount,
                                      const std::filesystem::path& source);

// One table with a `face` column (and a `keyframe` column when withKeyframes): each face's rows of
// the frames it is present in, is a keyframe in or has points in, by frame then face.
TrackTable joinFaceTruth(const std::vector<FaceTruth>& faces, bool withKeyframes);

// Written atomically (writeTrackTable); loading reads what saving wrote (or a `clm3d track
// --faces` output: no keyframes). InputError naming the file as splitFaceTruth's.
void saveFaceGroundTruth(const std::filesystem::path& csv, const std::vector<FaceTruth>& faces);
std::vector<FaceTruth> loadFaceGroundTruth(const std::filesystem::path& csv);

}  // namespace clm3d
