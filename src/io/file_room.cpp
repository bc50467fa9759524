// Reserved room for HDF5 writes and serial files read back (include/gradfric/io/file_room.hpp).
#include "gradfric/io/file_room.hpp"

#include "gradfric/io/collective_file.hpp"
#include "gradfric/io/hdf5_attributes.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gradfric::io {

namespace {

// Back to `size` bytes, nothing allocated past them (what a reservation added).
void giveBack(int fd, off_t size) {
  const int ignored = ftruncate(fd, size);
  (void)ignored;
  fallocate(fd, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, size, std::numeric_limits<off_t>::max() - size);
}

}  // namespace

std::string reserveRoom(const std::string& path, std::uint64_t bytes) {
  const int fd = open(path.c_str(), O_WRONLY);
  if (fd < 0) return std::strerror(errno);
  struct stat s {};
  int error = fstat(fd, &s) == 0 ? 0 : errno;
  // From the end HDF5 has written, keeping the size: a later reservation overlaps this one's
  // unused part instead of adding to it. KEEP_SIZE skips the file-size limit: checked here.
  struct rlimit limit {};
  if (!error && getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      static_cast<std::uint64_t>(s.st_size) + bytes > limit.rlim_cur)
    error = EFBIG;
  if (!error && fallocate(fd, FALLOC_FL_KEEP_SIZE, s.st_size, static_cast<off_t>(bytes)) != 0) {
    error = errno;
    // Not supported here: room past the end instead (zeros written past the end, where nothing
    // else writes, if the file system must emulate it); HDF5 accepts a file longer than its data.
    if (error == EOPNOTSUPP || error == ENOSYS) error = posix_fallocate(fd, s.st_size, static_cast<off_t>(bytes));
  }
  if (error) giveBack(fd, s.st_size);  // a partial reservation; the file's content is untouched either way
  close(fd);
  return error ? std::strerror(error) : "";
}

void releaseRoom(const std::string& path) {
  const int fd = open(path.c_str(), O_WRONLY);
  if (fd < 0) return;
  struct stat s {};
  if (fstat(fd, &s) == 0) giveBack(fd, s.st_size);  // (where the file system cannot, the room stays)
  close(fd);
}

namespace {

herr_t readAttributes(hid_t root, const char* name, const H5O_info_t*, void* error) {
  try {  // no exception may cross HDF5's C frames
    H5Object object(GF_H5(H5Oopen(root, name, H5P_DEFAULT)));
    readStringAttributes(object);
    return 0;
  } catch (const std::exception& e) {
    static_cast<std::string*>(error)->assign(e.what());
    return -1;
  }
}

// Every object and attribute of a closed file read back: a record HDF5 failed to write shows here.
void readBack(const std::string& path) {
  H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
  std::string error;
  const herr_t status = H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_NATIVE, readAttributes, &error, H5O_INFO_BASIC);
  if (!error.empty()) throw Hdf5Error(error);
  GF_H5(status);
}

// The file's last writes happen at its close, which the handle does not report.
void closeChecked(H5File& file) {
  GF_H5(H5Fflush(file, H5F_SCOPE_LOCAL));
  GF_H5(H5Fclose(file.release()));
}

// An empty HDF5 file made in memory: its first bytes then go where room was reserved.
std::vector<char> emptyFileImage() {
  H5PropertyList access(GF_H5(H5Pcreate(H5P_FILE_ACCESS)));
  GF_H5(H5Pset_fapl_core(access, 4096, 0));
  H5File memory(GF_H5(H5Fcreate("gradfric-empty-image", H5F_ACC_TRUNC, H5P_DEFAULT, access)));
  GF_H5(H5Fflush(memory, H5F_SCOPE_LOCAL));
  std::vector<char> image(static_cast<size_t>(GF_H5(H5Fget_file_image(memory, nullptr, 0))));
  GF_H5(H5Fget_file_image(memory, image.data(), image.size()));
  return image;
}

}  // namespace

void createEmptyHdf5File(const std::string& path, std::uint64_t bytes) {
  FileWriteScope scope(path);
  const std::vector<char> image = emptyFileImage();
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw Hdf5Error(writeFailure(path, std::strerror(errno)));
  const bool written = write(fd, image.data(), image.size()) == static_cast<ssize_t>(image.size());
  const int error = errno;
  close(fd);
  if (!written) throw Hdf5Error(writeFailure(path, std::strerror(error)));
  if (const std::string room = reserveRoom(path, bytes); !room.empty())
    throw Hdf5Error(writeFailure(path, "no room for its " + std::to_string(bytes) + " bytes: " + room));
}

void createHdf5File(const std::string& path, std::uint64_t bytes, const std::function<void(hid_t)>& build) {
  createEmptyHdf5File(path, bytes);
  FileWriteScope scope(path);
  H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)));
  build(file);
  closeChecked(file);
  releaseRoom(path);
  readBack(path);
}

void changeHdf5File(const std::string& path, std::uint64_t bytes, const std::function<void(hid_t)>& change) {
  FileWriteScope scope(path);
  const std::string room = bytes > 0 ? reserveRoom(path, bytes) : "";
  if (!room.empty())
    throw Hdf5Error(writeFailure(path, "no room for " + std::to_string(bytes) + " more bytes: " + room +
                                           " (the file is unchanged)"));
  H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)));
  change(file);
  closeChecked(file);
  releaseRoom(path);
  readBack(path);
}

void writeWholeFile(const std::string& path, const std::string& text) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw std::runtime_error(writeFailure(path, std::strerror(errno)));
  size_t done = 0;
  int error = 0;
  while (done < text.size() && !error) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) done += static_cast<size_t>(n);
  }
  if (close(fd) != 0 && !error) error = errno;
  if (error) throw std::runtime_error(writeFailure(path, std::strerror(error)));
}

}  // namespace gradfric::io
