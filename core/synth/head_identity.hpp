// Who a procedural head is (HeadIdentity: proportions in millimetres, colours) and what its face
// is doing (Expression: weights of a few facial actions). Kept apart from the generator so that
// tests, the CLI and the demo can draw populations of identities, and so that an identity drawn
// from a seed is the same on every machine and standard library.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d {

// A colour as sRGB components in [0, 1].
struct ColourRgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  bool operator==(const ColourRgb&) const = default;
};

// The shape and colouring of one synthetic person. Lengths are millimetres, angles degrees.
// "Eye line" is the horizontal line through the two eye centres; landmark 1 (centre between the
// eyes) lies on it. The defaults are an average adult; randomIdentity draws others.
// validate() states the allowed range of every field.
struct HeadIdentity {
  // Skull.
  double headWidth = 150.0;   // skull breadth above the ears, [130, 175]
  double headDepth = 195.0;   // brow to back of the head, [170, 220]
  double headHeight = 125.0;  // eye line to the top of the skull, [105, 145]
  // Face outline.
  double faceWidth = 126.0;    // across the lower cheeks at mouth level, [105, 145]
  double faceHeight = 120.0;   // eye line to the bottom of the chin, [100, 140]
  double cheekFullness = 0.5;  // cheekbone and cheek volume, [0, 1]
  // Eyes and brows.
  double eyeSpacing = 63.0;    // between the eye (iris) centres, [54, 74]
  double eyeWidth = 29.0;      // inner to outer eye corner, [23, 35]
  double eyeOpening = 10.0;    // lid margin to lid margin at the iris, [7, 13]
  double eyeCant = 4.0;        // outer corner raised by this angle, [-5, 12]
  double irisRadius = 5.8;     // [5, 6.5]
  double browHeight = 16.0;    // brow centre line above the eye line at its inner end, [10, 24]
  double browThickness = 5.0;  // [2, 9]
  double browArch = 3.5;       // rise of the brow's arch above its ends, [0, 8]
  // Nose.
  double noseLength = 44.0;      // eye line to the nose tip, [34, 56]
  double noseWidth = 34.0;       // between the alar bases, [26, 46]
  double noseProjection = 20.0;  // tip height above the cheek plane, [12, 30]
  // Mouth and chin.
  double mouthHeight = 71.0;       // eye line to the lips' meeting line, [58, 88]
  double mouthWidth = 50.0;        // corner to corner, [38, 66]
  double upperLipThickness = 7.5;  // height of the upper red lip at the middle, [3, 13]
  double lowerLipThickness = 9.5;  // height of the lower red lip at the middle, [4, 15]
  double chinWidth = 40.0;         // [28, 56]
  double chinProjection = 6.0;     // [0, 14]
  // Ears.
  double earHeight = 62.0;      // [48, 76]
  double earPosition = -22.0;   // ear centre relative to the eye line (negative = below), [-38, -5]
  double earProtrusion = 22.0;  // angle of the ear away from the head, [5, 40]
  // Hair.
  double foreheadHeight = 62.0;  // eye line to the front hairline, [40, 95]
  double hairBulk = 6.0;         // thickness of the hair over the skull, [0, 15]
  // Colours and fine detail.
  ColourRgb skinTone{0.86, 0.68, 0.57};
  ColourRgb irisColour{0.33, 0.22, 0.12};
  ColourRgb hairColour{0.23, 0.16, 0.11};
  double lipRedness = 0.5;       // [0, 1]
  std::uint64_t detailSeed = 1;  // pores, hair strands and skin blotches

  // Throws InputError naming the first field outside its range, or proportions that cannot
  // form a face (the mouth must lie at least 16 mm below the nose tip and 30 mm above the chin).
  void validate() const;
  bool operator==(const HeadIdentity&) const = default;
};

// An identity drawn from a seed: every field from a clipped normal distribution around the
// average adult (standard deviations of a few millimetres), colours from skin, iris and hair
// palettes. Deterministic: the same seed gives the same identity on every platform.
HeadIdentity randomIdentity(std::uint64_t seed);

// Facial actions, each 0 (absent) to 1 (strong). Combinations are allowed.
struct Expression {
  double mouthOpen = 0.0;   // jaw drops up to 18 mm, lips part, mouth interior shows
  double smile = 0.0;       // mouth corners out and up, cheeks raised, eyes slightly narrowed
  double frown = 0.0;       // inner brows down and together, mouth corners down
  double browRaise = 0.0;   // brows up, eyes wider
  double eyesNarrow = 0.0;  // lids close towards the iris centre (squint)

  // Throws InputError if a weight is outside [0, 1].
  void validate() const;
  bool operator==(const Expression&) const = default;

  // Named presets: see expressionPresetNames().
  // Throws InputError listing the valid names for an unknown name.
  static Expression preset(std::string_view name);
};

// "neutral", "smile", "surprise", "open-mouth", "frown", "squint".
std::vector<std::string> expressionPresetNames();

}  // namespace clm3d
