#include <functional>
#include <utility>

#include "core/common/error.hpp"
#include "core/fit/detail/optimiser_factories.hpp"
#include "core/fit/optimiser.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {
namespace {

using Factory = std::unique_ptr<Optimiser> (*)(const OptimiserSettings&);

const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> entries = {
      // OPTIMISER ENTRIES (one line each: {"name", &makeXOptimiser},)
      {"gauss-newton", &makeGaussNewtonOptimiser},
      {"fastncc", &makeFastNccOptimiser},
      {"powell", &makePowellOptimiser},
      {"nelder-mead", &makeNelderMeadOptimiser},
      {"condensation", &makeCondensationOptimiser},
      {"rlms", &makeRlmsOptimiser},
  };
  return entries;
}

}  // namespace

std::unique_ptr<Optimiser> makeOptimiser(std::string_view name, const OptimiserSettings& settings) {
  for (const auto& [entryName, factory] : registry()) {
    if (entryName == name) return factory(settings);
  }
  std::string valid;
  for (const auto& entry : registry()) valid += (valid.empty() ? "" : ", ") + entry.first;
  throw InputError("unknown optimiser '" + std::string(name) + "' (valid: " + valid + ")");
}

const std::vector<std::string>& optimiserNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> result;
    for (const auto& entry : registry()) result.push_back(entry.first);
    return result;
  }();
  return names;
}

std::string resolveOptimiser(std::string_view name, const ClmModel& model) {
  if (name != kAutoOptimiser) return std::string(name);
  bool experts = !model.views.empty();
  for (const ViewModel& view : model.views) {
    for (const PatchModel& patches : view.scales) experts = experts && patches.hasExperts();
  }
  return experts && !model.refiner.check.empty() ? "rlms" : "fastncc";
}

const std::vector<std::string>& optimiserChoices() {
  static const std::vector<std::string> choices = [] {
    std::vector<std::string> result{std::string(kAutoOptimiser)};
    for (const auto& entry : registry()) result.push_back(entry.first);
    return result;
  }();
  return choices;
}

}  // namespace clm3d
