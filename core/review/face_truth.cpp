#include "core/review/face_truth.hpp"

#include <algorithm>
#include <charconv>
#include <tuple>

#include "core/common/error.hpp"
#include "core/eval/face_pairing.hpp"

namespace clm3d {
namespace {

int faceId(const std::string& cell, const std::filesystem::path& source) {
  int id = -1;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), id);
  if (ec != std::errc() || end != cell.data() + cell.size() || id < 0) {
    throwInputError(source, "column face: \"" + cell + "\" is not a face id (0, 1, ...)");
  }
  return id;
}

bool anyPoint(const TrackRow& row) {
  for (Eigen::Index i = 0; i < row.points.cols(); ++i) {
    if (row.points.col(i).allFinite()) return true;
  }
  return false;
}

}  // namespace

std::vector<FaceTruth> splitFaceTruth(const TrackTable& table, int frameCount,
                                      const std::filesystem::path& source) {
  std::vector<FaceTruth> faces;
  for (const FaceTable& split : splitFaces(table)) {
    FaceTruth face;
    face.face = split.face.empty() ? 0 : faceId(split.face, source);
    face.truth = groundTruthFromTable(split.table, frameCount, source);
    face.present.assign(static_cast<std::size_t>(frameCount), false);
    for (const TrackRow& row : split.table.rows)
      face.present[static_cast<std::size_t>(row.frame)] = true;
    faces.push_back(std::move(face));
  }
  std::sort(faces.begin(), faces.end(),
            [](const FaceTruth& a, const FaceTruth& b) { return a.face < b.face; });
  return faces;
}

TrackTable joinFaceTruth(const std::vector<FaceTruth>& faces, bool withKeyframes) {
  TrackTable joined;
  joined.extraColumns = {"face"};
  if (withKeyframes) joined.extraColumns.push_back("keyframe");
  std::vector<std::tuple<int, int, const TrackRow*, bool>> rows;  // frame, face, row, keyframe
  for (const FaceTruth& face : faces) {
    joined.landmarkCount = std::max(joined.landmarkCount, face.truth.table.landmarkCount);
    for (std::size_t f = 0; f < face.truth.table.rows.size(); ++f) {
      const TrackRow& row = face.truth.table.rows[f];
      const bool keyframe = f < face.truth.keyframe.size() && face.truth.keyframe[f];
      const bool present = f < face.present.size() && face.present[f];
      if (present || keyframe || anyPoint(row))
        rows.emplace_back(row.frame, face.face, &row, keyframe);
    }
  }
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
  });
  for (const auto& [frame, face, row, keyframe] : rows) {
    TrackRow copy = *row;
    copy.extraCells = {std::to_string(face)};
    if (withKeyframes) copy.extraCells.push_back(keyframe ? "1" : "0");
    joined.rows.push_back(std::move(copy));
  }
  return joined;
}

void saveFaceGroundTruth(const std::filesystem::path& csv, const std::vector<FaceTruth>& faces) {
  writeTrackTable(csv, joinFaceTruth(faces, true));
}

std::vector<FaceTruth> loadFaceGroundTruth(const std::filesystem::path& csv) {
  const TrackTable table = readTrackTable(csv);
  int frames = 0;
  for (const TrackRow& row : table.rows) frames = std::max(frames, row.frame + 1);
  return splitFaceTruth(table, std::min(frames, kMaxGroundTruthFrames), csv);
}

}  // namespace clm3d
