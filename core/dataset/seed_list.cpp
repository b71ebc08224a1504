#include "core/dataset/detail/seed_list.hpp"

#include <charconv>
#include <set>
#include <stdexcept>
#include <string>

namespace clm3d {
namespace {

constexpr std::uint64_t kMaxSeeds = 100000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::uint64_t parseNumber(std::string_view s, std::string_view item) {
  s = trim(s);
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
    throw std::invalid_argument("'" + std::string(item) +
                                "' is not a seed (a non-negative integer) or a range a-b");
  }
  return value;
}

}  // namespace

std::vector<std::uint64_t> parseSeedList(std::string_view text) {
  std::vector<std::uint64_t> seeds;
  std::set<std::uint64_t> seen;
  auto add = [&](std::uint64_t seed) {
    if (!seen.insert(seed).second) {
      throw std::invalid_argument("seed " + std::to_string(seed) + " is listed twice");
    }
    if (seeds.size() >= kMaxSeeds) {
      throw std::invalid_argument("more than " + std::to_string(kMaxSeeds) + " seeds");
    }
    seeds.push_back(seed);
  };
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) comma = text.size();
    const std::string_view item = trim(text.substr(start, comma - start));
    if (item.empty()) throw std::invalid_argument("empty item in the seed list");
    const std::size_t dash = item.find('-');
    if (dash == std::string_view::npos) {
      add(parseNumber(item, item));
    } else {
      const std::uint64_t first = parseNumber(item.substr(0, dash), item);
      const std::uint64_t last = parseNumber(item.substr(dash + 1), item);
      if (first > last) {
        throw std::invalid_argument("range '" + std::string(item) + "' ends before it starts");
      }
      if (last - first >= kMaxSeeds) {
        throw std::invalid_argument("more than " + std::to_string(kMaxSeeds) + " seeds");
      }
      for (std::uint64_t s = first;; ++s) {
        add(s);
        if (s == last) break;
      }
    }
    start = comma + 1;
  }
  return seeds;
}

}  // namespace clm3d
