#include "gradfric/study/study_file.hpp"

#include "gradfric/io/file_room.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <algorithm>
#include <cstdint>

namespace gradfric::study {

void writeVector(hid_t group, const std::string& name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  io::H5Space space(GF_H5(H5Screate_simple(1, &n, nullptr)));
  io::H5Dataset set(GF_H5(H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
  if (n) GF_H5(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()));
}

void writeText(hid_t object, const std::string& name, const std::string& value) {
  io::H5Type type(GF_H5(H5Tcopy(H5T_C_S1)));
  GF_H5(H5Tset_size(type, std::max<size_t>(value.size(), 1)));
  io::H5Space space(GF_H5(H5Screate(H5S_SCALAR)));
  io::H5Attribute a(GF_H5(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT)));
  GF_H5(H5Awrite(a, type, value.c_str()));
}

io::OutputPlan planStudyFile(MPI_Comm comm, const std::string& output, bool overwrite) {
  io::OutputRequest request;
  request.option = "-output";
  request.path = output;
  request.temporarySuffix = ".partial";
  request.overwrite = overwrite;
  request.overwriteOption = "-output_overwrite";
  return io::OutputPlan::decide(comm, request);
}

std::vector<std::pair<std::string, std::string>> studyAttributes(
    const RunParameters& record, const std::vector<std::pair<std::string, std::string>>& first) {
  std::vector<std::pair<std::string, std::string>> attributes = {{"format", "gradfric-accuracy-study"}};
  attributes.insert(attributes.end(), first.begin(), first.end());
  for (const auto& option : record.all())
    attributes.emplace_back(option.name[0] == '-' ? option.name.substr(1) : option.name, option.value);
  return attributes;
}

void saveStudyFile(MPI_Comm comm, const io::OutputPlan& plan, const StudyFile& content) {
  std::uint64_t bytes = 0;  // the room reserved for it (io/file_room.hpp: a full disk is a clean error)
  for (const auto& [name, value] : content.attributes) bytes += name.size() + value.size() + 64;
  for (const auto& ladder : content.ladders) {
    for (const auto& [name, value] : ladder.texts) bytes += name.size() + value.size() + 64;
    for (const auto& [name, values] : ladder.columns) bytes += 8 * values.size() + 1024;
  }
  plan.writeOnRank0(comm, [&](const std::string& path) {
    io::createHdf5File(path, io::withMetadataRoom(bytes), [&](hid_t file) {
      for (const auto& [name, value] : content.attributes) writeText(file, name, value);
      for (const auto& ladder : content.ladders) {
        io::H5Group group(GF_H5(H5Gcreate2(file, ladder.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
        for (const auto& [name, value] : ladder.texts) writeText(group, name, value);
        for (const auto& [name, values] : ladder.columns) writeVector(group, name, values);
      }
    });
  });
  plan.commit(comm);
}

}  // namespace gradfric::study
