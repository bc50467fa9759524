#pragma once
// HDF5 never writes into space that may not exist. HDF5 1.10 does not report every failed write
// (a dataset's last bytes reach the disk when its handle closes, and handles close silently), and
// after one it may crash or loop when the library shuts down; in a parallel file the ranks
// would disagree inside a collective call and wait for ever. So the room a write needs is
// reserved first (fallocate past the file's end: a full disk, a quota or a file-size limit shows
// there, as the system's reason, before the file is touched), given back once the file is
// complete, and a file written serially is read back once closed.
#include "gradfric/io/hdf5_handle.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace gradfric::io {

// Allocates `bytes` past the end of path (which exists), its size unchanged where the file system
// allows. "" on success, else the reason ("No space left on device"); the file is then as it was.
std::string reserveRoom(const std::string& path, std::uint64_t bytes);
// Gives back what is left of the room past the end of a file that is complete.
void releaseRoom(const std::string& path);

// Serial. Writes path (replaced) as an empty HDF5 file followed by `bytes` reserved, for a writer
// that opens it read-write (in parallel: PETSc's viewer in FILE_MODE_APPEND). Throws Hdf5Error.
void createEmptyHdf5File(const std::string& path, std::uint64_t bytes);

// Serial. Writes path (replaced) as a new HDF5 file: an empty file with `bytes` reserved, build
// fills it, then it is closed and read back. Throws Hdf5Error naming the file and the reason;
// the caller removes the file.
void createHdf5File(const std::string& path, std::uint64_t bytes, const std::function<void(hid_t file)>& build);

// Serial. Changes an existing HDF5 file: `bytes` reserved past its end (none for a change in
// place, such as a scalar attribute rewritten), opened read-write, change applied, closed and
// read back. Throws Hdf5Error; when the room cannot be reserved, the message says that the file
// was left unchanged.
void changeHdf5File(const std::string& path, std::uint64_t bytes, const std::function<void(hid_t file)>& change);

// Serial. Writes a whole text file with write(2), every failure reported (a stream would lose
// the one of its last flush). Throws std::runtime_error naming the file and the reason.
void writeWholeFile(const std::string& path, const std::string& text);

// Room for HDF5's own records (object headers, heaps, B-trees) besides the data: generous, as
// running short means writing outside the reservation.
inline std::uint64_t withMetadataRoom(std::uint64_t dataBytes) { return dataBytes + dataBytes / 4 + (256u << 10); }

}  // namespace gradfric::io
