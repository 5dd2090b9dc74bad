// VectorValues: a grid's vectors, one contiguous run of x y z floats, either
// allocated here or adopted from memory a reading library filled (VTK's float
// array of a .vti), so that a field read from a file is held once instead of
// twice: the reader's array and a copy (loading at the grid's size, not 2x).
//
// An adopted run stays alive through its owner (any shared object: the
// library's reference-counted array) until the last VectorValues using it
// goes, and is written in place. A copy is deep and owns its memory, so a
// VectorValues behaves as a std::vector<glm::vec3> does.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

class VectorValues {
 public:
  VectorValues() = default;
  // Owns `values` (implicit: a std::vector is a grid's values as it stands).
  VectorValues(std::vector<glm::vec3> values);  // NOLINT(google-explicit-constructor)
  // `count` vectors at `data`, kept alive by `owner`.
  static VectorValues adopt(glm::vec3* data, std::size_t count, std::shared_ptr<void> owner);

  VectorValues(const VectorValues& other);
  VectorValues& operator=(const VectorValues& other);
  VectorValues(VectorValues&& other) noexcept;
  VectorValues& operator=(VectorValues&& other) noexcept;
  ~VectorValues() = default;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Whether the memory is another library's (adopt), for tests and logs.
  bool adopted() const { return owner_ != nullptr; }

  glm::vec3& operator[](std::size_t i) { return data_[i]; }
  const glm::vec3& operator[](std::size_t i) const { return data_[i]; }
  std::span<glm::vec3> span() { return {data_, size_}; }
  std::span<const glm::vec3> span() const { return {data_, size_}; }

 private:
  std::vector<glm::vec3> own_;   // the values, unless adopted
  std::shared_ptr<void> owner_;  // keeps adopted values alive
  glm::vec3* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace sandstorm
