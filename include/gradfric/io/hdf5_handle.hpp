#pragma once
// Small helpers around the HDF5 C API: a throwing check and RAII ownership of hid_t handles.
#include "gradfric/core/unique_handle.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <string>

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

// Owns one HDF5 identifier (core/unique_handle.hpp); the destructor calls the matching close function.
template <herr_t (*Close)(hid_t)>
struct Hdf5Close {
  static hid_t empty() { return H5I_INVALID_HID; }
  static bool valid(hid_t id) { return id >= 0; }
  static void close(hid_t id) { Close(id); }
};

template <herr_t (*Close)(hid_t)>
using Hdf5Handle = UniqueHandle<hid_t, Hdf5Close<Close>>;

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
