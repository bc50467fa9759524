#pragma once
// Small helpers around the HDF5 C API: a throwing check and RAII ownership of hid_t handles.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace gradfric::io {

class Hdf5Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
  // reason: the innermost entry of HDF5's error stack when the call failed ("" if none).
  Hdf5Error(const std::string& what, std::string reason) : std::runtime_error(what), reason_(std::move(reason)) {}
  const std::string& reason() const { return reason_; }

private:
  std::string reason_;
};

[[noreturn]] void throwHdf5Error(const char* expression, const char* file, int line);

// Owns one HDF5 identifier; the destructor calls the matching close function.
template <herr_t (*Close)(hid_t)>
class Hdf5Handle {
public:
  Hdf5Handle() = default;
  explicit Hdf5Handle(hid_t id) : id_(id) {}
  ~Hdf5Handle() { reset(); }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Gives up ownership without closing (the caller closes and checks the result).
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }
  void reset() {
    if (id_ >= 0) Close(id_);
    id_ = H5I_INVALID_HID;
  }

private:
  hid_t id_ = H5I_INVALID_HID;
};

using H5File = Hdf5Handle<H5Fclose>;
using H5Group = Hdf5Handle<H5Gclose>;
using H5Dataset = Hdf5Handle<H5Dclose>;
using H5Space = Hdf5Handle<H5Sclose>;
using H5Type = Hdf5Handle<H5Tclose>;
using H5Attribute = Hdf5Handle<H5Aclose>;
using H5PropertyList = Hdf5Handle<H5Pclose>;
using H5Object = Hdf5Handle<H5Oclose>;

}  // namespace gradfric::io

// Throws gradfric::io::Hdf5Error when an HDF5 call returns a negative value.
#define GF_H5(...)                                                                         \
  ([&]() {                                                                                 \
    auto gf_h5_result_ = (__VA_ARGS__);                                                    \
    if (gf_h5_result_ < 0) ::gradfric::io::throwHdf5Error(#__VA_ARGS__, __FILE__, __LINE__); \
    return gf_h5_result_;                                                                  \
  }())
