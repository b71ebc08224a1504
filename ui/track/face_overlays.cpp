#include "ui/track/face_overlays.hpp"

#include <array>

namespace clm3d::ui {

QColor faceColour(int face) {
  // Saturated and far apart in hue, readable on skin and on dark or light backgrounds.
  static const std::array<QColor, 6> colours{QColor(0, 200, 255),  QColor(255, 140, 0),
                                             QColor(220, 60, 220), QColor(60, 220, 60),
                                             QColor(255, 230, 0),  QColor(255, 80, 80)};
  const auto count = static_cast<int>(colours.size());
  return colours[static_cast<std::size_t>(((face % count) + count) % count)];
}

std::vector<FaceOverlay> otherFaceOverlays(const TrackSession& session, int frame) {
  std::vector<FaceOverlay> overlays;
  if (!session.multiFace()) return overlays;
  for (const TrackSession::Face& face : session.faces()) {
    if (face.id == session.selectedFace()) continue;
    if (const TrackRow* row = session.truthRow(face.id, frame)) {
      overlays.push_back({face.id, row->points, faceColour(face.id)});
    }
  }
  return overlays;
}

}  // namespace clm3d::ui
