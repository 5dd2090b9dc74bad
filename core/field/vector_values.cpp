#include "core/field/vector_values.h"

#include <utility>

namespace sandstorm {

VectorValues::VectorValues(std::vector<glm::vec3> values)
    : own_(std::move(values)), data_(own_.data()), size_(own_.size()) {}

VectorValues VectorValues::adopt(glm::vec3* data, std::size_t count, std::shared_ptr<void> owner) {
  VectorValues v;
  v.owner_ = std::move(owner);
  v.data_ = data;
  v.size_ = count;
  return v;
}

VectorValues::VectorValues(const VectorValues& other)
    : own_(other.data_, other.data_ + other.size_), data_(own_.data()), size_(own_.size()) {}

VectorValues& VectorValues::operator=(const VectorValues& other) {
  if (this != &other) *this = VectorValues(other);
  return *this;
}

// A moved std::vector keeps its buffer, so data_ stays valid for owned values.
VectorValues::VectorValues(VectorValues&& other) noexcept
    : own_(std::move(other.own_)),
      owner_(std::move(other.owner_)),
      data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)) {
  other.own_.clear();
}

VectorValues& VectorValues::operator=(VectorValues&& other) noexcept {
  if (this == &other) return *this;
  own_ = std::move(other.own_);
  owner_ = std::move(other.owner_);
  data_ = std::exchange(other.data_, nullptr);
  size_ = std::exchange(other.size_, 0);
  other.own_.clear();
  return *this;
}

}  // namespace sandstorm
