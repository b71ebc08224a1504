#include "core/dataset/detail/obj_vertex_picker.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace clm3d {

ObjVertexPicker::ObjVertexPicker(std::vector<int> wanted) : wanted_(std::move(wanted)) {
  int largest = -1;
  for (const int w : wanted_) largest = std::max(largest, w);
  slotOf_.assign(static_cast<std::size_t>(largest + 1), -1);
  for (std::size_t k = 0; k < wanted_.size(); ++k) {
    if (wanted_[k] >= 0) slotOf_[static_cast<std::size_t>(wanted_[k])] = static_cast<int>(k);
  }
  points_.setConstant(3, static_cast<Eigen::Index>(wanted_.size()),
                      std::numeric_limits<double>::quiet_NaN());
}

void ObjVertexPicker::feed(std::string_view chunk) {
  while (!chunk.empty()) {
    const void* found = std::memchr(chunk.data(), '\n', chunk.size());
    if (!found) {
      carry_.append(chunk);
      return;
    }
    const std::size_t length =
        static_cast<std::size_t>(static_cast<const char*>(found) - chunk.data());
    if (carry_.empty()) {
      line(chunk.substr(0, length));
    } else {
      carry_.append(chunk.substr(0, length));
      line(carry_);
      carry_.clear();
    }
    chunk.remove_prefix(length + 1);
  }
}

void ObjVertexPicker::line(std::string_view text) {
  ++lineNumber_;
  if (text.size() < 2 || text[0] != 'v' || (text[1] != ' ' && text[1] != '\t')) return;
  const std::size_t index = vertexCount_++;
  if (index >= slotOf_.size() || slotOf_[index] < 0) return;
  const char* p = text.data() + 2;
  const char* end = text.data() + text.size();
  double xyz[3];
  for (double& value : xyz) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    const auto [next, ec] = std::from_chars(p, end, value);
    if (ec != std::errc() || !std::isfinite(value)) {
      throw std::invalid_argument("line " + std::to_string(lineNumber_) +
                                  ": a vertex needs three finite numbers");
    }
    p = next;
  }
  points_.col(slotOf_[index]) = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
}

Eigen::Matrix3Xd ObjVertexPicker::finish() {
  if (!carry_.empty()) {
    line(carry_);
    carry_.clear();
  }
  if (slotOf_.size() > vertexCount_) {
    throw std::invalid_argument("has " + std::to_string(vertexCount_) + " vertices; vertex " +
                                std::to_string(slotOf_.size() - 1) + " is needed");
  }
  return points_;
}

}  // namespace clm3d
