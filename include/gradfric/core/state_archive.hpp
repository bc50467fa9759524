#pragma once
// The state of a running simulation as bytes, for checkpoints (fem/checkpoint.hpp). One function
// per object, archive(StateArchive&), both saves and restores it: each member is named once, in one
// order, so the two directions cannot drift apart. Each record carries its name and size, and a
// restore that meets another name or size throws CheckpointMismatch naming both (a checkpoint of
// another build or scene). Values are copied as their bytes: the restored run continues bit for bit.
// PETSc-free.
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace gradfric {

struct CheckpointMismatch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class StateArchive {
public:
  // An empty archive to save into.
  StateArchive() = default;
  // An archive to restore from these bytes.
  explicit StateArchive(std::vector<char> bytes) : bytes_(std::move(bytes)), restoring_(true) {}

  bool restoring() const { return restoring_; }
  const std::vector<char>& bytes() const { return bytes_; }
  // Restoring: every byte was read (a checkpoint with more state than the run is another run's).
  void expectEnd() const;

  // One value of a trivially copyable type.
  template <class T>
  void field(const char* name, T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "StateArchive copies bytes: give it plain values");
    record(name, &value, sizeof(T), false);
  }
  template <class T>
  void field(const char* name, std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "StateArchive copies bytes: give it plain values");
    std::size_t count = values.size();
    record(name, &count, sizeof count, false);
    if (restoring_) values.resize(count);
    record(name, values.data(), count * sizeof(T), true);
  }
  // A vector whose length the restored object already has (per-site state of a built law): a
  // different length is a mismatch, not a resize.
  template <class T>
  void fixedField(const char* name, std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "StateArchive copies bytes: give it plain values");
    record(name, values.data(), values.size() * sizeof(T), false);
  }

private:
  void record(const char* name, void* data, std::size_t size, bool sizedBefore);
  std::vector<char> bytes_;
  std::size_t at_ = 0;
  bool restoring_ = false;
};

}  // namespace gradfric
