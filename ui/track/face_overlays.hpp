// How the Track page shows a video tracked face by face (`clm3d track --faces`): a colour per face
// id, and the faces other than the selected one as the frame view's overlays (their ground-truth
// points of a frame). The overlays are copies: nothing here keeps a reference to the session.
#pragma once

#include <QColor>
#include <vector>

#include "core/review/track_session.hpp"
#include "ui/track/frame_view.hpp"

namespace clm3d::ui {

// Distinct colours for the first faces, repeating after them.
QColor faceColour(int face);

// The session's faces other than the selected one that have points on `frame`.
std::vector<FaceOverlay> otherFaceOverlays(const TrackSession& session, int frame);

}  // namespace clm3d::ui
