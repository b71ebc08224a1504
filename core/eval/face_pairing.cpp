#include "core/eval/face_pairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

constexpr const char* kFaceColumn = "face";

int faceColumnOf(const TrackTable& table) {
  const auto at = std::find(table.extraColumns.begin(), table.extraColumns.end(), kFaceColumn);
  return at == table.extraColumns.end() ? -1 : static_cast<int>(at - table.extraColumns.begin());
}

// Mean distance between two rows' points present in both, over the truth's eye distance; nullopt
// when either has no usable point or eye distance.
std::optional<double> rowError(const TrackRow& truth, const TrackRow& tracked,
                               std::pair<int, int> eyes) {
  if (truth.points.cols() != tracked.points.cols() || truth.points.cols() == 0) return {};
  const double iod = (truth.points.col(eyes.first) - truth.points.col(eyes.second)).norm();
  if (!std::isfinite(iod) || iod <= 0.0) return {};
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < truth.points.cols(); ++i) {
    if (!truth.points.col(i).allFinite() || !tracked.points.col(i).allFinite()) continue;
    sum += (truth.points.col(i) - tracked.points.col(i)).norm();
    ++count;
  }
  if (count == 0) return {};
  return sum / count / iod;
}

}  // namespace

bool hasFaceColumn(const TrackTable& table) {
  return faceColumnOf(table) >= 0;
}

std::vector<FaceTable> splitFaces(const TrackTable& table) {
  const int column = faceColumnOf(table);
  if (column < 0) return {{"", table}};
  TrackTable empty;
  empty.landmarkCount = table.landmarkCount;
  empty.extraColumns = table.extraColumns;
  empty.extraColumns.erase(empty.extraColumns.begin() + column);
  std::vector<FaceTable> faces;
  std::map<std::string, std::size_t> indexOf;
  for (const TrackRow& row : table.rows) {
    const auto k = static_cast<std::size_t>(column);
    const std::string face = k < row.extraCells.size() ? row.extraCells[k] : std::string();
    if (face.empty()) continue;  // an unreadable frame's row: no face
    auto [at, fresh] = indexOf.emplace(face, faces.size());
    if (fresh) faces.push_back({face, empty});
    TrackRow copy = row;
    if (k < copy.extraCells.size()) copy.extraCells.erase(copy.extraCells.begin() + column);
    faces[at->second].table.rows.push_back(std::move(copy));
  }
  return faces;
}

std::vector<FacePair> pairFaces(const TrackTable& truth, const TrackTable& tracked,
                                const Scheme& scheme, const std::string& trackedName) {
  if (truth.landmarkCount != tracked.landmarkCount) {
    throw InputError(fileMessage(trackedName, std::to_string(tracked.landmarkCount) +
                                                  " landmarks, the truth has " +
                                                  std::to_string(truth.landmarkCount)));
  }
  const auto eyes = scheme.normalisationPair();
  const std::vector<FaceTable> truthFaces = splitFaces(truth);
  const std::vector<FaceTable> trackedFaces = splitFaces(tracked);

  // Every truth face against every tracked face: mean error over shared frames.
  struct Candidate {
    double error = 0.0;
    int shared = 0;
    std::size_t t = 0, p = 0;
  };
  std::vector<Candidate> candidates;
  for (std::size_t t = 0; t < truthFaces.size(); ++t) {
    std::map<int, const TrackRow*> truthRows;
    for (const TrackRow& row : truthFaces[t].table.rows) truthRows[row.frame] = &row;
    for (std::size_t p = 0; p < trackedFaces.size(); ++p) {
      double sum = 0.0;
      int shared = 0;
      for (const TrackRow& row : trackedFaces[p].table.rows) {
        const auto at = truthRows.find(row.frame);
        if (!row.success || at == truthRows.end()) continue;
        if (const auto error = rowError(*at->second, row, eyes)) {
          sum += *error;
          ++shared;
        }
      }
      if (shared > 0 && sum / shared <= 1.0) candidates.push_back({sum / shared, shared, t, p});
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.error < b.error; });
  std::vector<FacePair> pairs(truthFaces.size());
  std::vector<bool> trackedUsed(trackedFaces.size(), false);
  for (std::size_t t = 0; t < truthFaces.size(); ++t) {
    pairs[t].pairing.truthFace = truthFaces[t].face;
    pairs[t].truth = truthFaces[t].table;
    pairs[t].tracked.landmarkCount = tracked.landmarkCount;
  }
  for (const Candidate& c : candidates) {
    FacePair& pair = pairs[c.t];
    if (pair.pairing.paired || trackedUsed[c.p]) continue;
    trackedUsed[c.p] = true;
    pair.pairing.paired = true;
    pair.pairing.trackedFace = trackedFaces[c.p].face;
    pair.pairing.sharedFrames = c.shared;
    pair.tracked = trackedFaces[c.p].table;
  }

  // Identity switches: per truth frame, the id of the nearest succeeded tracked row.
  std::map<int, std::vector<std::pair<std::string, const TrackRow*>>> trackedByFrame;
  for (const FaceTable& face : trackedFaces) {
    for (const TrackRow& row : face.table.rows) {
      if (row.success) trackedByFrame[row.frame].push_back({face.face, &row});
    }
  }
  for (FacePair& pair : pairs) {
    std::optional<std::string> last;
    for (const TrackRow& row : pair.truth.rows) {
      const auto at = trackedByFrame.find(row.frame);
      if (at == trackedByFrame.end()) continue;
      double best = 1.0;
      std::optional<std::string> nearest;
      for (const auto& [face, candidate] : at->second) {
        const auto error = rowError(row, *candidate, eyes);
        if (error && *error <= best) {
          best = *error;
          nearest = face;
        }
      }
      if (!nearest) continue;
      if (last && *last != *nearest) ++pair.pairing.idSwitches;
      last = nearest;
    }
  }
  return pairs;
}

}  // namespace clm3d
