// The command line: integers without wrap-around, finite reals, near misses, options files checked before
// PETSc reads them, run lengths refused before any work.
#include "gradfric/core/command_line.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/near_miss.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/run_limits.hpp"

#include "../common/scoped_option.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gradfric;

namespace {
using gradfric::testing::ScopedOption;

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The files go to a folder of their own under the working directory (the build tree under ctest).
const std::string kFolder = "test_command_line_files/";

std::string writeFile(const std::string& name, const std::string& content) {
  const std::string path = kFolder + name;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

std::string checkFile(const char* option, const std::string& path) {
  std::vector<std::string> args = {"prog", option, path};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return checkOptionFiles(static_cast<int>(argv.size()), argv.data());
}
}  // namespace

TEST(CommandLine, IntegersAreRangeCheckedNotWrapped) {
  OptionReader reader(PETSC_COMM_SELF, "t3_", "test", nullptr);
  for (const char* value : {"4294967304", "99999999999999999999", "-5", "1", "4097"}) {
    ScopedOption n("-t3_N", value);
    EXPECT_EQ(messageOf([&] { reader.integer("N", 60, 2, 4096, "1", "blocks"); }),
              std::string("invalid option -t3_N = ") + value + ": allowed 2 <= N <= 4096");
  }
  for (const char* value : {"1e3", "0x10", "", "12abc"}) {
    ScopedOption n("-t3_N", value);
    EXPECT_NE(messageOf([&] { reader.integer("N", 60, 2, 4096, "1", "blocks"); }).find("an integer"), std::string::npos)
        << value;
  }
  ScopedOption n("-t3_N", "4096");
  EXPECT_EQ(reader.integer("N", 60, 2, 4096, "1", "blocks"), 4096);
}

TEST(CommandLine, RealsMustBeFiniteAndRepresentable) {
  OptionReader reader(PETSC_COMM_SELF, "t4_", "test", nullptr);
  for (const char* value : {"inf", "-inf", "nan", "1e999", "1e-320", "", "1e-6x"}) {
    ScopedOption x("-t4_x", value);
    EXPECT_NE(messageOf([&] { reader.real("x", 1.0, "s", "a time"); }).find("-t4_x"), std::string::npos) << value;
    ScopedOption list("-t4_list", (std::string("1,") + value + ",2").c_str());
    if (value[0]) {
      EXPECT_NE(messageOf([&] { reader.realList("list", {}, "s", "times"); }).find("-t4_list"), std::string::npos) << value;
    }
  }
  ScopedOption x("-t4_x", "-1.5e300");
  EXPECT_EQ(reader.real("x", 1.0, "s", "a time"), -1.5e300);
}

TEST(CommandLine, NearMissesOfKnownOptions) {
  EXPECT_EQ(editDistance("output", "ouput"), 1u);
  EXPECT_EQ(editDistance("output", "outptu"), 1u);  // a swap of neighbours counts once
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  const std::vector<std::string> known = {"-output", "-sbm_N", "-ensemble_realisations", "-model"};
  EXPECT_EQ(nearMiss("-ouput", known), "-output");
  EXPECT_EQ(nearMiss("--sbm_N", known), "-sbm_N");
  EXPECT_EQ(nearMiss("-ensmble_realisatons", known), "-ensemble_realisations");
  EXPECT_EQ(nearMiss("-mdoel", known), "-model");
  EXPECT_EQ(nearMiss("-log_view", known), "");
  EXPECT_EQ(nearMiss("-output", known), "");  // the option itself is not a miss
  EXPECT_TRUE(isPetscOptionName("log_view"));
  EXPECT_TRUE(isPetscOptionName("ts_monitor"));
  EXPECT_TRUE(isPetscOptionName("malloc_debug"));
  EXPECT_TRUE(isPetscOptionName("options_left"));
  EXPECT_FALSE(isPetscOptionName("ouput"));
  EXPECT_FALSE(isPetscOptionName("sbm_N"));
}

TEST(CommandLine, UnusedNearMissIsRefusedAndPetscOptionsPass) {
  OptionReader reader(PETSC_COMM_SELF, "t5_", "test", nullptr);
  reader.real("width", 1.0, "m", "a width");
  {
    ScopedOption typo("-t5_widht", "2");
    EXPECT_NE(messageOf([] { checkUnusedOptions(PETSC_COMM_SELF, {}); }).find("did you mean -t5_width?"),
              std::string::npos);
  }
  ScopedOption petsc("-ts_monitor", "");
  EXPECT_EQ(messageOf([] { checkUnusedOptions(PETSC_COMM_SELF, {}); }), "");
}

TEST(CommandLine, OptionsFilesAreCheckedBeforePetscReadsThem) {
  EXPECT_EQ(checkFile("-options_file", writeFile("good.opts", "-sbm_N 5 # comment\n\n-sbm_dt 1e-8\n")), "");
  EXPECT_EQ(checkFile("-options_file", writeFile("empty.opts", "")), "");
  EXPECT_EQ(checkFile("-options_file_yaml", writeFile("good.yaml", "sbm:\n  N: 5\n  dt: 1e-8\n")), "");
  EXPECT_NE(checkFile("-options_file", writeFile("binary.opts", std::string("-a 1\0\1", 6))).find("binary data"),
            std::string::npos);
  EXPECT_NE(checkFile("-options_file", writeFile("latin1.opts", "-a \xe9t\xe9\n")).find("not UTF-8"), std::string::npos);
  EXPECT_NE(checkFile("-options_file", writeFile("words.opts", "hello world\n")).find("line 1"), std::string::npos);
  EXPECT_NE(checkFile("-options_file", ".").find("a directory"), std::string::npos);
  EXPECT_NE(checkFile("-options_file", "no_such_file.opts").find("No such file"), std::string::npos);
  EXPECT_NE(checkFile("-options_file_yaml", writeFile("bad.yaml", "a: [1, 2\nb: }\n")).find("not valid YAML"),
            std::string::npos);
  EXPECT_NE(checkFile("-options_file_yaml", writeFile("list.yaml", "- 1\n- 2\n")).find("mapping"), std::string::npos);
  // A nested file is named relative to the file that includes it.
  const std::string self = kFolder + "self.opts";
  writeFile("self.opts", "-options_file self.opts\n");
  EXPECT_NE(checkFile("-options_file", self).find("includes itself"), std::string::npos);
  const std::string a = kFolder + "a.opts", b = kFolder + "b.opts";
  writeFile("a.opts", "-x 1\n-options_file b.opts\n");
  writeFile("b.opts", "-options_file a.opts\n");
  EXPECT_NE(checkFile("-options_file", a).find("includes itself (" + a + " -> " + b + " -> " + a + ")"),
            std::string::npos)
      << checkFile("-options_file", a);
}

SettledCommandLine settle(std::vector<std::string> args) {
  args.insert(args.begin(), "prog");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return settleCommandLine(static_cast<int>(argv.size()), argv.data());
}

TEST(CommandLine, OptionsFilesAreExpandedWithTheirPathsTheirOwn) {
  writeFile("scene/inner.opts", "-field_mu_map maps/m.png\n-sbm_N 7\n");
  writeFile("scene/outer.opts",
            "alias -n -sbm_N\n-options_file inner.opts   # nested: beside this file\n"
            "-pressure_response_file \"g.h5\"\n-n 9\n");
  const std::string outer = kFolder + "scene/outer.opts";
  const SettledCommandLine s = settle({"-options_file", outer, "-plot_dir", "figures", "-help", "fem"});
  EXPECT_EQ(s.problem, "");
  const std::vector<std::string> expected = {"prog",    "-field_mu_map", "maps/m.png", "-sbm_N", "7",
                                             "-pressure_response_file", "g.h5", "-sbm_N", "9",
                                             "-plot_dir", "figures", "-help"};
  EXPECT_EQ(s.arguments, expected);
  EXPECT_EQ(s.helpFilter, "fem");
  EXPECT_EQ(s.folders.at("-field_mu_map"), kFolder + "scene");
  EXPECT_EQ(s.folders.at("-pressure_response_file"), kFolder + "scene");
  EXPECT_EQ(s.folders.at("-plot_dir"), "");
  // The last setting decides where a path is read from: the command line's is the working directory's.
  EXPECT_EQ(settle({"-options_file", outer, "-field_mu_map", "x.png"}).folders.at("-field_mu_map"), "");
  EXPECT_EQ(settle({"-field_mu_map", "x.png", "-options_file", outer}).folders.at("-field_mu_map"), kFolder + "scene");
}

TEST(CommandLine, StrayWordsAreRefusedNamingTheOption) {
  EXPECT_EQ(settle({"-ensemble_delta", "0", "0.2"}).problem,
            "invalid option -ensemble_delta = 0 0.2: allowed one value (the stray word 0.2 would be ignored; a list "
            "is comma-separated without spaces: 0,0.2)");
  EXPECT_NE(settle({"-a", "-1e-3", "-2", "-b"}).problem.find("invalid option -a = -1e-3 -2: allowed one value"),
            std::string::npos);
  EXPECT_EQ(settle({"word", "-a", "1"}).problem, "invalid word 'word' on the command line: allowed options (-name [value]) only");
  const std::string file = writeFile("stray.opts", "-a 1\n-b 2 3 4\n");
  EXPECT_NE(settle({"-options_file", file}).problem.find("invalid option -b = 2 3 4 (in " + file + " line 2): allowed one value (the stray words 3 4"),
            std::string::npos);
  // Numbers (-inf, -1e6) are values, not options; -a -b are two flags; "a b" quoted in a file is one value.
  EXPECT_EQ(settle({"-a", "-inf", "-b", "-c", "-1e6"}).problem, "");
  EXPECT_EQ(settle({"-options_file", writeFile("quoted.opts", "-title \"a b\"\n")}).problem, "");
}

TEST(CommandLine, EmptyListItemsAreRefused) {
  OptionReader reader(PETSC_COMM_SELF, "t9_", "test", nullptr);
  for (const char* value : {"0.1,,0.2", "0.1,", ",0.1", "0.1, ,0.2"}) {
    ScopedOption list("-t9_list", value);
    EXPECT_NE(messageOf([&] { reader.realList("list", {}, "1", "values"); }).find("is empty"), std::string::npos) << value;
    ScopedOption choices("-t9_choices", value);
    EXPECT_NE(messageOf([&] { reader.choiceList("choices", {}, {"0.1", "0.2"}, "c"); }).find("is empty"), std::string::npos)
        << value;
  }
  ScopedOption list("-t9_list", "0.1, 0.2");
  EXPECT_EQ(reader.realList("list", {}, "1", "values"), (std::vector<double>{0.1, 0.2}));
}

TEST(CommandLine, DoubleDashesAndHelpAreNormalised) {
  std::vector<std::string> args = {"prog", "--sbm_N", "9", "--help", "-h", "-1e6", "--", "-x"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  normaliseArguments(static_cast<int>(argv.size()), argv.data());
  const std::vector<std::string> expected = {"prog", "-sbm_N", "9", "-help", "-help", "-1e6", "--", "-x"};
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(argv[i], expected[i]) << i;
  EXPECT_FALSE(versionRequested(static_cast<int>(argv.size()), argv.data()));
}

TEST(CommandLine, EndlessRunsAreRefusedNamingTheOptionTheUserSet) {
  RunParameters record;
  record.add({"-sbm_dt", "1e-300", "s", "", OptionOrigin::User, ""});
  record.add({"-sbm_mu_s", "0.5", "1", "", OptionOrigin::Default, "0.5"});
  // The automatic step would be fine: the step the user set is to blame.
  EXPECT_NE(messageOf([&] { requireRunLength(&record, 1e-3, 1e-300, 1e-8, "-sbm_dt", {"-sbm_t_max"}, {"-sbm_"}, "t_max"); })
                .find("invalid option -sbm_dt = 1e-300"),
            std::string::npos);
  RunParameters physical;
  physical.add({"-sbm_mu_s", "1e+300", "1", "", OptionOrigin::User, "0.5"});
  physical.add({"-sbm_v", "0.02", "m/s", "", OptionOrigin::User, "0.01"});
  EXPECT_NE(messageOf([&] { requireRunLength(&physical, 1e297, 1e-8, 1e-8, "-sbm_dt", {"-sbm_t_max"}, {"-sbm_"}, "t_max"); })
                .find("invalid option -sbm_mu_s = 1e+300"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { requireRunLength(&physical, std::nan(""), 1e-8, 1e-8, "-sbm_dt", {}, {"-sbm_"}, "t_max"); }),
            "");
  EXPECT_EQ(messageOf([&] { requireRunLength(&physical, 1e-3, 1e-8, 1e-8, "-sbm_dt", {}, {"-sbm_"}, "t_max"); }), "");
  EXPECT_NE(messageOf([&] { requireResolvedTimescale(&physical, 1e-300, 1e-8, "-sbm_dt", {"-sbm_"}, "loading time"); })
                .find("-sbm_mu_s"),
            std::string::npos);
}
