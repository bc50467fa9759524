// io::OutputPlan on every rank of PETSC_COMM_WORLD: each refusal is the same InputError on every
// rank; the temporary is renamed onto the target only by commit(), which replaces an earlier
// file whole and reports a failed rename (naming both paths) on every rank; a failing writer on
// rank 0 is an error on every rank, and leaves the earlier file whole.
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/io/output_plan.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

using namespace gradfric;
using namespace gradfric::io;

namespace {

MPI_Comm comm() { return PETSC_COMM_WORLD; }
int rank() {
  int r = 0;
  MPI_Comm_rank(comm(), &r);
  return r;
}

// The folders rank 0 made, removed when the process exits (they held only this run's files).
struct ScratchFolders {
  std::vector<std::string> paths;
  ~ScratchFolders() {
    std::error_code ignored;
    for (const std::string& path : paths) std::filesystem::remove_all(path, ignored);
  }
};
ScratchFolders scratchFolders;

// A fresh folder for one test, the same path on every rank (rank 0 creates it).
std::string folder(const char* name) {
  char buffer[256] = "";
  if (rank() == 0) {
    std::snprintf(buffer, sizeof buffer, "output_plan_%s_%d", name, static_cast<int>(getpid()));
    EXPECT_EQ(std::system((std::string("rm -rf ") + buffer).c_str()), 0) << buffer;
    mkdir(buffer, 0755);
    scratchFolders.paths.push_back(buffer);
  }
  MPI_Bcast(buffer, sizeof buffer, MPI_CHAR, 0, comm());
  return buffer;
}

void writeText(const std::string& path, const std::string& text) {
  if (rank() == 0) std::ofstream(path) << text;
  MPI_Barrier(comm());
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool exists(const std::string& path) { return access(path.c_str(), F_OK) == 0; }

OutputRequest request(const std::string& path) {
  OutputRequest r;
  r.path = path;
  r.temporarySuffix = ".partial";
  return r;
}

// The message of the InputError decide() throws, "" if it does not; the same on every rank.
std::string refusal(const OutputRequest& r) {
  std::string message;
  try {
    OutputPlan::decide(comm(), r);
  } catch (const InputError& e) {
    message = e.what();
  }
  // Every rank must have thrown the same message (a refusal on rank 0 only would hang a run).
  int length = static_cast<int>(message.size()), lengthOn0 = length;
  MPI_Bcast(&lengthOn0, 1, MPI_INT, 0, comm());
  EXPECT_EQ(length, lengthOn0) << message;
  return message;
}

}  // namespace

TEST(OutputPlan, RefusesADirectoryAndLeavesItUntouched) {
  const std::string dir = folder("directory");
  writeText(dir + "/inside", "keep");
  const std::string message = refusal(request(dir));
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
  EXPECT_EQ(readText(dir + "/inside"), "keep");
}

TEST(OutputPlan, RefusesAMissingFolder) {
  const std::string message = refusal(request(folder("missing") + "/no/such/folder/x.h5"));
  EXPECT_NE(message.find("existing, writable folder"), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST(OutputPlan, RefusesAnExistingFileWithoutOverwriteAndNamesTheOptions) {
  const std::string path = folder("existing") + "/x.h5";
  writeText(path, "earlier");
  OutputRequest r = request(path);
  r.resumeOption = "-resume";
  const std::string message = refusal(r);
  EXPECT_NE(message.find("-output_overwrite"), std::string::npos) << message;
  EXPECT_NE(message.find("-resume"), std::string::npos) << message;
  r.overwrite = true;
  EXPECT_EQ(refusal(r), "");
  EXPECT_EQ(readText(path), "earlier");  // planning deletes nothing
  r.resume = true;
  EXPECT_NE(refusal(r).find("conflicting options"), std::string::npos);
}

TEST(OutputPlan, RefusesAnInterruptedRunWithoutResume) {
  const std::string path = folder("interrupted") + "/x.h5";
  writeText(path + ".partial", "half");
  OutputRequest r = request(path);
  r.resumeOption = "-resume";
  EXPECT_NE(refusal(r).find("interrupted run"), std::string::npos);
  r.resume = true;
  const OutputPlan plan = OutputPlan::decide(comm(), r);
  EXPECT_EQ(plan.start(), OutputStart::ContinueTemporary);
  EXPECT_EQ(plan.workPath(), path + ".partial");
  EXPECT_EQ(readText(path + ".partial"), "half");
}

TEST(OutputPlan, ResumesAFinishedFileInPlaceAndStartsFreshWithoutOne) {
  const std::string path = folder("resume") + "/x.h5";
  OutputRequest r = request(path);
  r.resume = true;
  r.resumeOption = "-resume";
  EXPECT_EQ(OutputPlan::decide(comm(), r).start(), OutputStart::Fresh);
  EXPECT_FALSE(exists(path + ".partial"));  // the probe is removed again
  writeText(path, "done");
  const OutputPlan plan = OutputPlan::decide(comm(), r);
  EXPECT_EQ(plan.start(), OutputStart::ContinueFinished);
  EXPECT_EQ(plan.workPath(), path);
}

TEST(OutputPlan, RefusesATemporaryThatCannotBeCreated) {
  const std::string path = folder("temporary") + "/x.h5";
  if (rank() == 0) mkdir((path + ".partial").c_str(), 0755);
  MPI_Barrier(comm());
  const std::string message = refusal(request(path));
  EXPECT_NE(message.find("temporary file"), std::string::npos) << message;
}

TEST(OutputPlan, CommitReplacesTheEarlierFileOnlyThen) {
  const std::string path = folder("commit") + "/x.h5";
  writeText(path, "earlier");
  OutputRequest r = request(path);
  r.overwrite = true;
  const OutputPlan plan = OutputPlan::decide(comm(), r);
  plan.writeOnRank0(comm(), [](const std::string& work) { std::ofstream(work) << "new"; });
  MPI_Barrier(comm());
  EXPECT_EQ(readText(path), "earlier");  // written, not yet committed
  MPI_Barrier(comm());                   // every rank has looked before rank 0 renames
  plan.commit(comm());
  EXPECT_EQ(readText(path), "new");
  EXPECT_FALSE(exists(path + ".partial"));
}

TEST(OutputPlan, AFailedWriterIsAnErrorOnEveryRankAndKeepsTheEarlierFile) {
  const std::string path = folder("writer") + "/x.h5";
  writeText(path, "earlier");
  OutputRequest r = request(path);
  r.overwrite = true;
  const OutputPlan plan = OutputPlan::decide(comm(), r);
  std::string message;
  try {
    plan.writeOnRank0(comm(), [](const std::string& work) {
      std::ofstream(work) << "half";
      throw std::runtime_error("disk full (simulated)");
    });
  } catch (const CollectiveError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("disk full (simulated)"), std::string::npos) << message;
  EXPECT_EQ(readText(path), "earlier");
  EXPECT_FALSE(exists(path + ".partial"));
}

TEST(OutputPlan, AFailedRenameIsAnErrorOnEveryRankNamingBothPaths) {
  const std::string path = folder("rename") + "/x.h5";
  const OutputPlan plan = OutputPlan::decide(comm(), request(path));
  plan.writeOnRank0(comm(), [](const std::string& work) { std::ofstream(work) << "new"; });
  // The target became a non-empty directory after planning: rename(2) must fail.
  if (rank() == 0) {
    mkdir(path.c_str(), 0755);
    std::ofstream(path + "/inside") << "keep";
  }
  MPI_Barrier(comm());
  std::string message;
  try {
    plan.commit(comm());
  } catch (const CollectiveError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("cannot rename " + path + ".partial to " + path), std::string::npos) << message;
  EXPECT_EQ(readText(path + ".partial"), "new");  // the new result is kept under its temporary name
  EXPECT_EQ(readText(path + "/inside"), "keep");
}
