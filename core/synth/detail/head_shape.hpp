// The analytic surface of a procedural head, shared by the mesh builder, the texture painter and
// the landmark solver, so that landmarks lie exactly on the surface that is meshed and painted.
//
// The skin is a star-shaped surface seen from a centre C inside the head: along the direction
// d(theta, phi) = (sin theta cos phi, sin phi, cos theta cos phi) it lies at radius
// base(d) + relief(d). base is a smooth union of a skull ellipsoid, a jaw ellipsoid cut by the
// plane under the chin, and a neck; relief is the sum of facial features (brows, eyes, nose,
// lips, chin, cheeks, hair) placed in the face chart (X, Y) = the frontal (x, y) of the base
// point, millimetres with the origin at the midpoint of the eye centres. Ears are separate
// closed shells (EarShape) sunk into the side of the head.
// Coordinates here are the head's own; generateHead moves everything so that landmark 1 is at
// the origin.
#pragma once

#include <Eigen/Core>

#include "core/synth/head_identity.hpp"

namespace clm3d::synth {

// Where the features of one face are, in the face chart, after the expression is applied.
// "Left" (subject's left) is +X; right-side features are the mirror images.
struct FaceLayout {
  // Eyes: centre at (±eyeX, 0); corners at lx = ±eyeHalfWidth on the corner line y = eyeSlope lx.
  double eyeX = 0, eyeHalfWidth = 0, eyeUp = 0, eyeDown = 0, eyeSlope = 0;
  double irisRadius = 0, pupilRadius = 0;
  // Brows (left): centre line from (browInnerX, browInnerY) to (browOuterX, browOuterY).
  double browInnerX = 0, browOuterX = 0, browInnerY = 0, browOuterY = 0, browArch = 0;
  double browThickness = 0;
  // Nose.
  double nasionY = 0, tipY = 0, tipHeight = 0, bridgeHeight = 0, subnasaleY = 0;
  double alaX = 0, alaY = 0, alaHeight = 0, alarBaseX = 0, alarBaseY = 0;
  double nostrilX = 0, nostrilY = 0;
  // Mouth: lips meet on y = mouthY + cornerLift (X / mouthHalfWidth)^2; an open mouth parts them
  // by lipGap at the middle.
  double mouthY = 0, mouthHalfWidth = 0, cornerLift = 0, upperLip = 0, lowerLip = 0;
  double lipGap = 0, jawDrop = 0;
  // Chin, cheeks, brow furrows.
  double mentonY = 0, chinHalfWidth = 0, chinProjection = 0;
  double cheekHeight = 0, cheekY = 0, smileBulge = 0, foldDepth = 0, frown = 0;
  // Jaw-line landmarks (left).
  double cheekPointX = 0, cheekPointY = 0, chinPointX = 0, chinPointY = 0;
  // Hair.
  double foreheadHeight = 0, hairBulk = 0, earTop = 0;
};

FaceLayout makeLayout(const HeadIdentity& identity, const Expression& expression);

// The eye nearer to (X, Y), in its own frame: lx along the corner line towards the ear (so both
// eyes read alike), ly up from the eye centre.
struct EyeField {
  double lx = 0, ly = 0, t = 0;
  double upper = 0, lower = 0;  // lid margin heights at lx
  double opening = 0;           // > 0 inside the opening (mm, roughly)
  double aperture = 0;          // 1 inside the opening, 0 on the lids (0.6 mm transition)
  double region = 0;            // weight of the lids and eyeball against the surrounding skin
  double crease = 0;            // height of the upper-lid crease at lx
};
EyeField eyeField(const FaceLayout& layout, double X, double Y);

struct MouthField {
  double t = 0;     // X / half the mouth width
  double line = 0;  // where the lips meet (or the middle of the opening)
  double upperTop = 0, upperBottom = 0, lowerTop = 0, lowerBottom = 0;
  double upperLip = 0, lowerLip = 0;  // red-lip masks, sharp (0.4 mm) borders
  double interior = 0;                // open-mouth mask
  double width = 0;                   // (1 - t^2) clipped at 0
};
MouthField mouthField(const FaceLayout& layout, double X, double Y);

struct BrowField {
  double u = 0;       // 0 at the inner end, 1 at the outer end
  double across = 0;  // mm above the centre line
  double halfThickness = 0;
  double mask = 0;  // 1 inside the brow, soft edges
};
BrowField browField(const FaceLayout& layout, double X, double Y);

struct Ellipsoid {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axes = Eigen::Vector3d::Ones();
  // Distance along the unit direction dir from an inside point to the surface.
  double exitDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const;
};

struct SurfaceSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // the skin
  Eigen::Vector3d base = Eigen::Vector3d::Zero();      // the base point (no relief)
  double X = 0, Y = 0;                                 // face chart
  double front = 0;                                    // weight of the face features, 0..1
  double theta = 0, phi = 0;
  double hairline = 0;  // chart height of the hairline at this azimuth
};

class HeadShape {
 public:
  HeadShape(const HeadIdentity& identity, const Expression& expression);

  const HeadIdentity& identity() const { return identity_; }
  const FaceLayout& layout() const { return layout_; }
  const Ellipsoid& skull() const { return skull_; }
  const Eigen::Vector3d& centre() const { return centre_; }

  SurfaceSample sample(double theta, double phi) const;
  // The directions (theta, phi) whose base point has face chart coordinates (X, Y), on the face
  // side. Throws clm3d::Error if the chart point is not on the face.
  Eigen::Vector2d solveChart(double X, double Y) const;
  // The lowest face chart height on the mid-line (where the chin turns under).
  double chinBottomY() const;
  // The skin point at face chart (X, Y).
  Eigen::Vector3d pointAt(double X, double Y) const;
  // Relief of the face features at chart (X, Y), millimetres along the ray.
  double faceRelief(double X, double Y) const;

 private:
  double baseRadius(const Eigen::Vector3d& dir) const;
  double hairlineAt(double theta) const;

  HeadIdentity identity_;
  FaceLayout layout_;
  Eigen::Vector3d centre_;
  Ellipsoid skull_;
  Ellipsoid jaw_;
  Eigen::Vector3d chinPlaneNormal_;  // outward normal of the plane under the chin
  double chinPlaneOffset_ = 0;       // plane: normal . p = offset
  double neckCentreZ_ = 0, neckRadiusX_ = 0, neckRadiusZ_ = 0, neckBottom_ = 0, neckTop_ = 0;
};

// One ear (the left one, +x; the right ear is its mirror image): a closed shell made of a lateral
// and a medial sheet over the same outline, parametrised by rho in [0, 1] (centre to rim) and
// psi in [-pi, pi] (angle in the ear's plane; psi = -pi/2 is the bottom of the lobe, psi = ±pi
// the front edge, which is sunk into the head).
struct EarSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double concha = 0;  // depth of the bowl at this point, 0..1, for shading
  double rim = 0;     // helix rim weight, 0..1
  double lobe = 0;    // earlobe weight, 0..1
};

class EarShape {
 public:
  explicit EarShape(const HeadShape& head);
  EarSample sample(double rho, double psi, bool lateral) const;
  // Landmark 19: the lateral surface of the lobe.
  Eigen::Vector3d lobePoint() const;

 private:
  Eigen::Vector3d origin_, normal_, back_, up_;
  double halfWidth_ = 0, halfHeight_ = 0, protrusion_ = 0;
};

}  // namespace clm3d::synth
