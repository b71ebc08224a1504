// Two annotated photos side by side in one video, each moving on its own trajectory (the photo
// sequence's motion, core/eval/photo_sequence.hpp, with seeds `seed` and `seed + 1`), with exact
// truth per face: a test of tracking every face (`clm3d track --faces`) on real faces, written by
// `clm3d synth --photo A --landmarks A.pts --beside B --beside-landmarks B.pts`
// (docs/synthetic-sequences.md).
#pragma once

#include "core/eval/photo_sequence.hpp"

namespace clm3d {

struct PhotoPairSummary {
  int frames = 0;
  cv::Size frameSize;  // two halves side by side
  TrackTable truth;    // two rows a frame, by face (column `face`: 0 left, 1 right)
};

// Each photo fills one half: settings.width x settings.height, or when 0 x 0 the larger of the
// two photos' sizes (rounded down to even), each photo centred in its half. Writes the video
// (lossless for .avi/.mkv), the truth (tracks CSV with success 1, confidence 1, the points moved by
// each face's transform, a `face` column) and sequence.json; files.visibility is not written (the
// truth's points are all inside their half by construction of the motion ranges). InputError for
// bad settings, photos that are not 8-bit BGR or points photoFace refuses. Progress 0..1;
// Cancelled between frames leaves no video.
PhotoPairSummary writePhotoPairSequence(const cv::Mat& left, const LandmarkSet& leftPoints,
                                        const cv::Mat& right, const LandmarkSet& rightPoints,
                                        const PhotoSequenceSettings& settings,
                                        const PhotoSequenceSource& leftSource,
                                        const PhotoSequenceSource& rightSource,
                                        const SequenceFiles& files,
                                        const ProgressCallback& progress = {},
                                        const CancelToken* cancel = nullptr);

}  // namespace clm3d
