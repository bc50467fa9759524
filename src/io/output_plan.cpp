#include "gradfric/io/output_plan.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/collective_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gradfric::io {

namespace {

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

bool exists(const std::string& path) {
  struct stat s {};
  return lstat(path.c_str(), &s) == 0;
}

bool isDirectory(const std::string& path) {
  struct stat s {};
  return stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

// Opens (creating if asked) a file for writing and closes it again: the check that the run will
// be able to write there. Returns 0 or the errno of the failure.
int probeWrite(const std::string& path, bool create) {
  const int fd = create ? open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644) : open(path.c_str(), O_RDWR);
  if (fd < 0) return errno;
  close(fd);
  return 0;
}

struct Decision {
  std::string refusal;  // the message of the InputError, or ""
  OutputStart start = OutputStart::Fresh;
};

// Rank 0: the file-system checks, in the order a user would fix them.
Decision decideHere(const OutputRequest& r) {
  const std::string& path = r.path;
  const std::string temporary = path + r.temporarySuffix;
  const std::string folder = folderOf(path);
  const bool resumable = !r.resumeOption.empty();
  const std::string& value = r.value.empty() ? path : r.value;
  auto refuse = [&](const std::string& allowed) { return Decision{InputError(r.option, value, allowed).what()}; };
  if (path.empty()) return Decision{InputError(r.option, "(empty)", "a file path").what()};
  if (isDirectory(path)) return refuse("a file path (" + path + " is a directory)");
  if (!isDirectory(folder)) return refuse("a path in an existing, writable folder (" + folder + " does not exist)");
  if (r.resume && r.overwrite)
    return Decision{"conflicting options: " + r.resumeOption + " continues " + path + ", " + r.overwriteOption +
                    " replaces it; give one of them"};
  if (r.extend && (r.overwrite || r.resume))
    return Decision{"conflicting options: " + r.extendOption + " extends " + path + ", " +
                    (r.overwrite ? r.overwriteOption + " replaces it" : r.resumeOption + " continues it as it is") +
                    "; give one of them (" + r.extendOption + " also continues an interrupted extension)"};
  if (isDirectory(temporary)) return refuse("a path whose temporary file " + temporary + " is not a directory");
  Decision d;
  if (r.extend && !exists(temporary) && !exists(path))
    return Decision{InputError(r.extendOption, "(set)", "a finished results file at " + r.option + " (" + path +
                                                            " does not exist)").what()};
  if (r.extend && exists(temporary)) {
    d.start = OutputStart::ContinueTemporary;  // an interrupted extension (checked against the scene later)
  } else if (r.extend) {
    d.start = OutputStart::ExtendFinished;
  } else if (r.resume && exists(temporary)) {
    d.start = OutputStart::ContinueTemporary;
  } else if (r.resume && exists(path)) {
    d.start = OutputStart::ContinueFinished;
  } else if (exists(path) && !r.overwrite) {
    return refuse("a file that does not exist yet (" + path + " exists: add " + r.overwriteOption + " to replace it" +
                  (resumable ? ", or " + r.resumeOption + " to continue it)" : ")"));
  } else if (resumable && exists(temporary) && !r.overwrite) {
    return refuse("a path without an interrupted run (" + temporary + " exists: add " + r.resumeOption +
                  " to continue it, or " + r.overwriteOption + " to start again)");
  }
  // Write access where the run will write: the temporary is created (and removed again), or the
  // file to continue is opened for writing.
  const std::string target = d.start == OutputStart::ContinueFinished ? path : temporary;
  const bool createsTemporary = d.start == OutputStart::Fresh || d.start == OutputStart::ExtendFinished;
  const int error = probeWrite(target, createsTemporary);
  if (createsTemporary) unlink(temporary.c_str());
  if (error)
    return refuse("a path in an existing, writable folder (cannot write " + target + ": " + std::strerror(error) + ")");
  return d;
}

}  // namespace

OutputPlan OutputPlan::decide(MPI_Comm comm, const OutputRequest& request) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Decision d;
  if (rank == 0) d = decideHere(request);
  broadcast(comm, d.refusal);
  if (!d.refusal.empty()) throw InputError(d.refusal);
  int start = static_cast<int>(d.start);
  GF_CALL_MPI(MPI_Bcast(&start, 1, MPI_INT, 0, comm));
  OutputPlan plan;
  plan.path_ = request.path;
  plan.start_ = static_cast<OutputStart>(start);
  plan.workPath_ = plan.start_ == OutputStart::ContinueFinished ? request.path : request.path + request.temporarySuffix;
  return plan;
}

void OutputPlan::writeOnRank0(MPI_Comm comm, const std::function<void(const std::string&)>& write) const {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0) {
    try {
      FileWriteScope scope(workPath_);  // an HDF5 failure names the file and the system's reason
      write(workPath_);
    } catch (const std::exception& e) {
      const std::string what = e.what();
      error = what.rfind("writing " + workPath_, 0) == 0 ? what : "writing " + workPath_ + " failed: " + what;
      if (workPath_ != path_) unlink(workPath_.c_str());
    }
  }
  agreeOnError(comm, error);
}

void OutputPlan::commit(MPI_Comm comm) const {
  if (workPath_ == path_) return;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string error;
  if (rank == 0 && std::rename(workPath_.c_str(), path_.c_str()) != 0)
    error = "cannot rename " + workPath_ + " to " + path_ + ": " + std::strerror(errno) + " (the new result stays in " +
            workPath_ + ")";
  agreeOnError(comm, error);
}

void OutputPlan::discard(MPI_Comm comm) const {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0 && workPath_ != path_) unlink(workPath_.c_str());
}

}  // namespace gradfric::io
