#include "core/synth/head_identity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

void checkRange(const char* name, double value, double low, double high) {
  if (!(value >= low && value <= high)) {
    std::ostringstream message;
    message << "head identity: " << name << " = " << value << " is outside [" << low << ", " << high
            << "]";
    throw InputError(message.str());
  }
}

void checkColour(const char* name, const ColourRgb& c) {
  for (double v : {c.r, c.g, c.b}) {
    if (!(v >= 0.0 && v <= 1.0)) {
      throw InputError(std::string("head identity: ") + name + " components must be in [0, 1]");
    }
  }
}

// mt19937_64 is fully specified by the standard; the std distributions are not, so the draws
// below are made by hand to stay identical across standard libraries.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed ^ 0x5eed5eed5eedULL) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double normal() {
    const double u1 = std::max(uniform(), 1e-300);
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  // mean + sd * N(0, 1), the normal clipped at 2.5 standard deviations.
  double around(double mean, double sd) { return mean + sd * std::clamp(normal(), -2.5, 2.5); }
  std::uint64_t bits() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

ColourRgb mix(const ColourRgb& a, const ColourRgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

// Piecewise-linear walk along a palette by t in [0, 1].
template <std::size_t N>
ColourRgb palette(const std::array<ColourRgb, N>& colours, double t) {
  const double x = std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1);
  const auto i = std::min(static_cast<std::size_t>(x), N - 2);
  return mix(colours[i], colours[i + 1], x - static_cast<double>(i));
}

}  // namespace

void HeadIdentity::validate() const {
  checkRange("headWidth", headWidth, 130, 175);
  checkRange("headDepth", headDepth, 170, 220);
  checkRange("headHeight", headHeight, 105, 145);
  checkRange("faceWidth", faceWidth, 105, 145);
  checkRange("faceHeight", faceHeight, 100, 140);
  checkRange("cheekFullness", cheekFullness, 0, 1);
  checkRange("eyeSpacing", eyeSpacing, 54, 74);
  checkRange("eyeWidth", eyeWidth, 23, 35);
  checkRange("eyeOpening", eyeOpening, 7, 13);
  checkRange("eyeCant", eyeCant, -5, 12);
  checkRange("irisRadius", irisRadius, 5, 6.5);
  checkRange("browHeight", browHeight, 10, 24);
  checkRange("browThickness", browThickness, 2, 9);
  checkRange("browArch", browArch, 0, 8);
  checkRange("noseLength", noseLength, 34, 56);
  checkRange("noseWidth", noseWidth, 26, 46);
  checkRange("noseProjection", noseProjection, 12, 30);
  checkRange("mouthHeight", mouthHeight, 58, 88);
  checkRange("mouthWidth", mouthWidth, 38, 66);
  checkRange("upperLipThickness", upperLipThickness, 3, 13);
  checkRange("lowerLipThickness", lowerLipThickness, 4, 15);
  checkRange("chinWidth", chinWidth, 28, 56);
  checkRange("chinProjection", chinProjection, 0, 14);
  checkRange("earHeight", earHeight, 48, 76);
  checkRange("earPosition", earPosition, -38, -5);
  checkRange("earProtrusion", earProtrusion, 5, 40);
  checkRange("foreheadHeight", foreheadHeight, 40, 95);
  checkRange("hairBulk", hairBulk, 0, 15);
  checkRange("lipRedness", lipRedness, 0, 1);
  checkColour("skinTone", skinTone);
  checkColour("irisColour", irisColour);
  checkColour("hairColour", hairColour);
  if (mouthHeight < noseLength + 16.0) {
    throw InputError("head identity: mouthHeight must be at least noseLength + 16 mm");
  }
  if (faceHeight < mouthHeight + 30.0) {
    throw InputError("head identity: faceHeight must be at least mouthHeight + 30 mm");
  }
  if (eyeWidth > eyeSpacing - 18.0) {
    throw InputError("head identity: eyeWidth must be at most eyeSpacing - 18 mm");
  }
}

HeadIdentity randomIdentity(std::uint64_t seed) {
  Draw draw(seed);
  HeadIdentity id;
  id.headWidth = draw.around(150, 6);
  id.headDepth = draw.around(195, 7);
  id.headHeight = draw.around(125, 5);
  id.faceWidth = draw.around(126, 5);
  id.faceHeight = draw.around(120, 5);
  id.cheekFullness = std::clamp(draw.around(0.5, 0.2), 0.0, 1.0);
  id.eyeSpacing = draw.around(63, 2.5);
  id.eyeWidth = draw.around(29, 1.4);
  id.eyeOpening = draw.around(10, 0.9);
  id.eyeCant = draw.around(4, 2);
  id.irisRadius = draw.around(5.8, 0.2);
  id.browHeight = draw.around(16, 1.8);
  id.browThickness = draw.around(5, 1);
  id.browArch = std::max(0.0, draw.around(3.5, 1.2));
  id.noseLength = draw.around(44, 2.8);
  id.noseWidth = draw.around(34, 2.5);
  id.noseProjection = draw.around(20, 2.2);
  id.mouthHeight = draw.around(71, 2.8);
  id.mouthWidth = draw.around(50, 3.2);
  id.upperLipThickness = draw.around(7.5, 1.3);
  id.lowerLipThickness = draw.around(9.5, 1.3);
  id.chinWidth = draw.around(40, 3.5);
  id.chinProjection = std::max(0.0, draw.around(6, 2));
  id.earHeight = draw.around(62, 3.5);
  id.earPosition = draw.around(-22, 2.5);
  id.earProtrusion = draw.around(22, 5);
  id.foreheadHeight = draw.around(62, 6);
  id.hairBulk = std::max(0.0, draw.around(6, 2));
  id.lipRedness = std::clamp(draw.around(0.5, 0.2), 0.0, 1.0);
  // Proportions that must hold together.
  id.mouthHeight = std::max(id.mouthHeight, id.noseLength + 18.0);
  id.faceHeight = std::max(id.faceHeight, id.mouthHeight + 34.0);
  id.faceHeight = std::min(id.faceHeight, 140.0);

  static constexpr std::array<ColourRgb, 6> kSkin{{{0.95, 0.80, 0.70},
                                                   {0.90, 0.72, 0.60},
                                                   {0.80, 0.60, 0.46},
                                                   {0.66, 0.46, 0.32},
                                                   {0.48, 0.32, 0.22},
                                                   {0.33, 0.22, 0.15}}};
  static constexpr std::array<ColourRgb, 6> kIris{{{0.20, 0.12, 0.06},
                                                   {0.35, 0.22, 0.10},
                                                   {0.45, 0.38, 0.18},
                                                   {0.30, 0.42, 0.28},
                                                   {0.32, 0.45, 0.60},
                                                   {0.45, 0.52, 0.58}}};
  static constexpr std::array<ColourRgb, 6> kHair{{{0.06, 0.05, 0.05},
                                                   {0.16, 0.10, 0.07},
                                                   {0.30, 0.20, 0.12},
                                                   {0.55, 0.42, 0.25},
                                                   {0.55, 0.25, 0.12},
                                                   {0.55, 0.53, 0.50}}};
  const double skin = draw.uniform();
  id.skinTone = palette(kSkin, skin);
  // Darker skins mostly come with darker irises and hair.
  id.irisColour = palette(kIris, std::clamp(draw.uniform() * (1.2 - skin), 0.0, 1.0));
  id.hairColour = palette(kHair, std::clamp(draw.uniform() * (1.15 - 0.8 * skin), 0.0, 1.0));
  id.detailSeed = draw.bits();
  return id;
}

void Expression::validate() const {
  const std::pair<const char*, double> fields[] = {{"mouthOpen", mouthOpen},
                                                   {"smile", smile},
                                                   {"frown", frown},
                                                   {"browRaise", browRaise},
                                                   {"eyesNarrow", eyesNarrow}};
  for (const auto& [name, value] : fields) {
    if (!(value >= 0.0 && value <= 1.0)) {
      std::ostringstream message;
      message << "expression: " << name << " = " << value << " is outside [0, 1]";
      throw InputError(message.str());
    }
  }
}

std::vector<std::string> expressionPresetNames() {
  return {"neutral", "smile", "surprise", "open-mouth", "frown", "squint"};
}

Expression Expression::preset(std::string_view name) {
  Expression e;
  if (name == "neutral") return e;
  if (name == "smile") {
    e.smile = 1.0;
    e.eyesNarrow = 0.2;
    return e;
  }
  if (name == "surprise") {
    e.browRaise = 1.0;
    e.mouthOpen = 0.55;
    return e;
  }
  if (name == "open-mouth") {
    e.mouthOpen = 1.0;
    return e;
  }
  if (name == "frown") {
    e.frown = 1.0;
    e.eyesNarrow = 0.15;
    return e;
  }
  if (name == "squint") {
    e.eyesNarrow = 0.7;
    e.smile = 0.2;
    return e;
  }
  std::string valid;
  for (const auto& n : expressionPresetNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("unknown expression '" + std::string(name) + "' (valid: " + valid + ")");
}

}  // namespace clm3d
