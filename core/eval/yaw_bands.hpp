// Pose-aware measurement for `clm3d eval-points --truth-dir`: each truth image gets a yaw (from a
// poses CSV such as AFLW's index.csv, or from the 3D model fitted to the truth's points) and the
// folder report gets, per |yaw| band and method, the faces, the faces fitted, the mean errors
// normalised by the face box and by the eye distance, and the share of points found
// (docs/evaluation.md, "Yaw bands"). The eye distance shrinks as the head turns, so at large pose
// the box-normalised error is the one to compare.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/eval/point_folder_error.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

// A poses CSV: a header with columns image and yaw_deg (others ignored, e.g. AFLW's
// image,yaw_deg,visible_count,split), one row per image; the image is matched by its file stem
// ("images/image04384.jpg" is image04384). InputError naming the file (and line): no such file,
// a missing column, a yaw that is not a finite number, an image listed twice.
std::map<std::string, double> readPoseCsv(const std::filesystem::path& file);

// Band edges from "0,30,60,90": at least two, finite, non-negative and strictly ascending;
// InputError otherwise.
std::vector<double> parseBandEdges(std::string_view text);

// The band of a yaw: k for edges[k] <= |yaw| < edges[k+1] (the last band includes its upper
// edge); -1 for a NaN yaw or one outside every band.
int yawBandOf(double yawDeg, const std::vector<double>& edges);

// The bands' names, "0-30" for edges 0 and 30 (whole degrees without decimals): one per band.
std::vector<std::string> yawBandLabels(const std::vector<double>& edges);

// Per report image the yaw of its stem in `poses`, NaN where the CSV does not list it.
std::vector<double> yawsByStem(const PointFolderReport& report,
                               const std::map<std::string, double>& poses);

// Per report image the yaw in degrees of the model's 3D shape fitted to the truth's present points
// (stateFromPoints), NaN for a truth with fewer than 4 present points. The photo is not read: the
// camera has the vertical field of view verticalFovDeg over an image twice the distance from the
// origin to the centre of the truth's box, i.e. the face at the image centre. InputError when the
// model's scheme does not have the truths' point count.
std::vector<double> yawsFromModel(const PointFolderReport& report, const ClmModel& model,
                                  double verticalFovDeg);

// The yaw in degrees of the model's 3D shape fitted to 2D points (stateFromPoints; columns in the
// model's scheme, NaN columns missing), NaN for fewer than 4 present points. The camera has the
// vertical field of view verticalFovDeg over an image twice the distance from the origin to the
// centre of the points' box. InputError when the column count is not the model's point count.
double fittedYawDeg(const ClmModel& model, const Eigen::Matrix2Xd& points, double verticalFovDeg);

// Sets report.yawDeg (one per image), bandEdges and yawSource, and fills every method's bands:
// a face is fitted when it has a prediction not marked rejected; the mean errors are over the
// fitted faces with a scored point; points of unfitted faces count as not found.
void addYawBands(PointFolderReport& report, std::vector<double> yawDeg, std::vector<double> edges,
                 std::string source);

// "yaw bands (SOURCE; N images in no band)" then a row per band and method:
// "|yaw| A-B  METHOD  faces F  fitted K (P%)  error/box E  median M  error/eye D  within T: X%".
std::string formatYawBandText(const PointFolderReport& report);

// The band table side by side as Markdown, the shape of docs/real-faces.md: a row per band with
// "| A-B | faces |" then per method "K (P%) | E |" (faces fitted, mean error / box). Faces are the
// truth's, the same for every method.
std::string formatYawBandMarkdown(const PointFolderReport& report);

}  // namespace clm3d
