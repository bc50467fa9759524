// The named records of a checkpoint's state (include/gradfric/core/state_archive.hpp).
#include "gradfric/core/state_archive.hpp"

#include <cstdint>

namespace gradfric {

namespace {

// Each record: name length, name, payload size, payload.
void append(std::vector<char>& bytes, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  bytes.insert(bytes.end(), p, p + size);
}

}  // namespace

void StateArchive::record(const char* name, void* data, std::size_t size, bool sizedBefore) {
  const std::uint32_t nameLength = static_cast<std::uint32_t>(std::strlen(name));
  const std::uint64_t payload = size;
  if (!restoring_) {
    append(bytes_, &nameLength, sizeof nameLength);
    append(bytes_, name, nameLength);
    append(bytes_, &payload, sizeof payload);
    if (size > 0) append(bytes_, data, size);
    return;
  }
  auto take = [&](void* out, std::size_t n) {
    if (at_ + n > bytes_.size())
      throw CheckpointMismatch(std::string("the checkpoint ends before the state '") + name + "'");
    if (n > 0) std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
  };
  std::uint32_t storedLength = 0;
  take(&storedLength, sizeof storedLength);
  if (storedLength > 4096 || at_ + storedLength > bytes_.size())
    throw CheckpointMismatch(std::string("the checkpoint is not readable at the state '") + name + "'");
  const std::string stored(bytes_.data() + at_, storedLength);
  at_ += storedLength;
  std::uint64_t storedPayload = 0;
  take(&storedPayload, sizeof storedPayload);
  if (stored != name)
    throw CheckpointMismatch("the checkpoint holds the state '" + stored + "' where this run has '" + name + "'");
  if (storedPayload != payload)
    throw CheckpointMismatch("the checkpoint's state '" + stored + "' has " + std::to_string(storedPayload) +
                             " bytes, this run's " + std::to_string(payload) +
                             (sizedBefore ? "" : " (another mesh, partition or law?)"));
  take(data, size);
}

void StateArchive::expectEnd() const {
  if (restoring_ && at_ != bytes_.size())
    throw CheckpointMismatch("the checkpoint holds " + std::to_string(bytes_.size() - at_) +
                             " bytes of state this run does not have");
}

}  // namespace gradfric
