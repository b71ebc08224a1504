// Picks a few vertices out of an OBJ text streamed in chunks, without building the mesh: only the
// `v` lines are counted (0-based, in file order, as the vertex indices of a landmark table are) and
// only the wanted ones parsed. Reading the 25 landmark vertices of the ~170 ICT-FaceKit meshes
// this way takes seconds instead of minutes.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d {

class ObjVertexPicker {
 public:
  // wanted[k] is the 0-based `v`-line index of output column k; negative = not wanted (NaN column).
  explicit ObjVertexPicker(std::vector<int> wanted);

  // Feeds the next chunk of the file; lines may span chunks. Throws std::invalid_argument
  // ("line N: ...") for a wanted `v` line that does not hold three finite numbers.
  void feed(std::string_view chunk);
  // After the last chunk: the wanted vertices as columns. Throws std::invalid_argument if the file
  // has fewer vertices than a wanted index needs.
  Eigen::Matrix3Xd finish();

  std::size_t vertexCount() const { return vertexCount_; }

 private:
  void line(std::string_view text);

  std::vector<int> wanted_;
  std::vector<int> slotOf_;  // v-line index -> output column, -1 (sized to the largest wanted + 1)
  Eigen::Matrix3Xd points_;
  std::string carry_;  // an unfinished line from the previous chunk
  std::size_t vertexCount_ = 0;
  std::size_t lineNumber_ = 0;
};

}  // namespace clm3d
