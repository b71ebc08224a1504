// The |yaw| band table as printed, one layout for `clm3d eval-points` (photos) and `clm3d eval`
// (frames of sequences): per band and method the faces, how many were fitted, the mean error over
// the truth's face box (and its median), over the eye distance, and the share of points found.
// Callers fill it from their own reports (yaw_bands.hpp, sequence_yaw_bands.hpp).
#pragma once

#include <string>
#include <vector>

namespace clm3d {

struct BandFigures {
  int faces = 0;          // photos or truth frames in the band
  int fitted = 0;         // of those, fitted (a prediction not rejected; a frame reported tracked)
  double boxError = 0.0;  // mean error / face box over the scored ones; NaN if none
  double medianBoxError = 0.0;  // its median; NaN if none
  double eyeError = 0.0;        // mean error / eye distance; NaN if none
  double foundShare = 0.0;      // points within the threshold / true points; NaN if none
  int offFace =
      -1;  // fitted ones whose error / box exceeds BandTable::offFaceAbove; -1: not counted
};

struct BandTable {
  std::vector<double> edges;  // |yaw| band edges, degrees (bands [e0,e1), ..., the last closed)
  std::string source;         // where the yaws came from
  int unbanded = 0;           // faces or frames in no band
  std::string faceWord = "faces";  // "faces" (photos) or "frames" (sequences)
  double threshold = 0.18;
  double offFaceAbove = 0.08;
  std::vector<std::string> labels;             // one per method
  std::vector<std::vector<BandFigures>> rows;  // [method][band]
};

// "yaw bands (SOURCE; N FACES in no band)" then a row per band and method: "|yaw| A-B  METHOD
// FACES F  fitted K (P%)  error/box E  median M  error/eye D  within T: X%", then, where counted,
// "  off the face (error/box > L): W".
std::string formatBandLines(const BandTable& table);

// Markdown, the methods side by side (docs/real-faces.md): "| \|yaw\| | photos | M fitted | M
// error / box |..." then "| A-B | F | K (P%) | E |..." per band (F from the first method).
std::string formatBandMarkdown(const BandTable& table, const std::string& facesTitle);

}  // namespace clm3d
