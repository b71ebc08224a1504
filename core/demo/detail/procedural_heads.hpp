// Procedural heads (core/synth) written as files a person or the trainer opens: OBJ (+ MTL, PNG
// texture) and LJSON landmarks (thesis25), seeds in a row with expression presets in turn, and
// a contact sheet of each head from the thesis's 15 training views to check at a glance that
// they look like faces. One writer for `clm3d synth-head` and `clm3d demo`. Heads are handed to
// the caller one at a time, so a long run keeps only what the caller keeps.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/synth/synth_head.hpp"

namespace clm3d {

struct WrittenHead {
  std::uint64_t seed = 0;
  std::string expression;           // preset name
  std::filesystem::path mesh;       // folder/head-<seed>.obj
  std::filesystem::path landmarks;  // folder/head-<seed>.ljson
};

// Called after each head is written, in seed order, on the calling thread; it may move the head.
using HeadWritten = std::function<void(const WrittenHead& written, SynthHead&& head)>;

// `count` heads, seeds firstSeed, firstSeed + 1, ..., head i with expressions[i % size],
// generated with `options` and written into `folder` (created). Throws InputError for an empty
// or unknown expression name or invalid options before anything is written.
void writeProceduralHeads(std::uint64_t firstSeed, int count,
                          const std::vector<std::string>& expressions, const SynthOptions& options,
                          const std::filesystem::path& folder, const HeadWritten& onHead);

struct HeadTiles {
  std::vector<cv::Mat> tiles;         // BGRA, tileSize x tileSize, one per training view
  std::vector<std::string> captions;  // "#<seed> y<yaw> p<pitch>"
};

// The head from each of the 15 training views, framed on the whole head and turned about the
// middle of the head and neck, for a contact sheet (core/viz/contact_sheet.hpp).
HeadTiles trainingViewTiles(const SynthHead& head, std::uint64_t seed, int tileSize);

}  // namespace clm3d
