// The bad-input corpus (tests/bad-inputs/cases.json) run through the built
// `lensrt`: each case gives the command line, the exit status and the exact
// message. Every case must finish within its time limit, print one error line
// (or, when it renders anyway, the expected warnings), and leave an existing
// output file byte-identical with no temporary file behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "robustness/run_util.h"

namespace lensrt::robustness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kInputs = fs::path(LENSRT_TEST_DATA_DIR) / "bad-inputs";
const std::string kPrecious = "an earlier render that must survive a failed run\n";

struct Case {
  std::string name;
  json spec;
};

std::vector<Case> loadCases() {
  std::ifstream in(kInputs / "cases.json");
  const json manifest = json::parse(in);
  std::vector<Case> cases;
  for (const json& c : manifest.at("cases")) cases.push_back({c.at("name").get<std::string>(), c});
  return cases;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// Placeholders: {in} the corpus directory, {tmp} the case's scratch directory,
// {out} an existing output file in it.
std::string expand(const std::string& s, const fs::path& tmp) {
  return replaceAll(replaceAll(replaceAll(s, "{out}", (tmp / "out.exr").string()), "{tmp}", tmp.string()),
                    "{in}", kInputs.string());
}

// `pattern` with "{*}" matching any text (for names with a process id).
bool matches(const std::string& text, const std::string& pattern) {
  const std::string star = "{*}";
  const std::size_t at = pattern.find(star);
  if (at == std::string::npos) return text == pattern;
  if (text.compare(0, at, pattern, 0, at) != 0) return false;
  const std::string rest = pattern.substr(at + star.size());
  for (std::size_t from = at; from <= text.size(); ++from)
    if (matches(text.substr(from), rest)) return true;
  return false;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.insert(fs::relative(e.path(), dir).string());
  return names;
}

bool isRoot() {
  return geteuid() == 0;
}

// A shell script for `unshare`: mounts what the case needs in a private mount
// namespace (gone when the process ends), runs lensrt, then copies what the
// test must check to a witness directory outside the mount.
//   $1 the directory to mount over, $2 the witness directory, $3 the precious file, then lensrt's argv.
std::string mountScript(const std::string& setup) {
  // full-disk: a 64 KiB tmpfs holding the precious output and a filler using
  // all the rest; nearly-full-disk: the same with 8 KiB left free (too little
  // for the image, found only when writing it).
  const std::string tmpfs =
      "mount -t tmpfs -o size=64k lensrt-full \"$1\" || exit 97; cp \"$3\" \"$1/out.exr\"; ";
  const std::string filler = "dd if=/dev/zero of=\"$1/filler\" bs=4096 >/dev/null 2>&1; ";
  const std::string reserve = "dd if=/dev/zero of=\"$1/reserve\" bs=4096 count=2 >/dev/null 2>&1; ";
  const std::string mount = setup == "full-disk" ? tmpfs + filler
                            : setup == "nearly-full-disk"
                                ? tmpfs + reserve + filler + "rm \"$1/reserve\"; "
                                : "cp \"$3\" \"$1/out.exr\"; mount --bind \"$1\" \"$1\" && mount -o "
                                  "remount,bind,ro \"$1\" || exit 97; ";
  return "d=$1 w=$2; " + mount +
         "touch \"$w/mounted\"; shift 3; \"$@\"; s=$?; cp \"$d/out.exr\" \"$w/out.exr\"; "
         "ls -A \"$d\" > \"$w/listing\"; exit $s";
}

class BadInputs : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputs, OneClearLineRightStatusNoHangOutputUntouched) {
  const json& c = GetParam().spec;
  if (c.contains("known_issue"))
    GTEST_SKIP() << "known issue, reported: " << c["known_issue"].get<std::string>();
  const TempDir tmp(GetParam().name);
  writeFile(tmp.path() / "out.exr", kPrecious);
  if (c.contains("generate")) {
    const json& g = c["generate"];
    std::ofstream out(tmp.path() / g.at("file").get<std::string>(), std::ios::binary);
    const std::string line = g.at("line");
    for (int i = 0; i < g.at("count").get<int>(); ++i) out << line;
  }
  std::vector<std::string> args{LENSRT_BINARY};
  for (const std::string a : c.at("args")) args.push_back(expand(a, tmp.path()));
  if (c.contains("env")) {  // run through env(1) with these variables set
    std::vector<std::string> withEnv{"env"};
    for (const auto& [name, value] : c["env"].items())
      withEnv.push_back(name + "=" + expand(value, tmp.path()));
    withEnv.insert(withEnv.end(), args.begin(), args.end());
    args = withEnv;
  }

  // Cases that need an unwritable or full directory get it from a private
  // mount namespace; the output directory is then `target`.
  const std::string setup = c.value("setup", "");
  fs::path target = tmp.path(), witness;
  if (!setup.empty()) {
    const bool full = setup == "full-disk" || setup == "nearly-full-disk";
    target = tmp.path() / (full ? "full" : "ro");
    witness = tmp.path() / "witness";
    fs::create_directories(target);
    fs::create_directories(witness);
    if (setup == "read-only-dir" && !isRoot()) {
      writeFile(target / "out.exr", kPrecious);
      fs::permissions(target, fs::perms::owner_read | fs::perms::owner_exec);
    } else {
      std::vector<std::string> wrapped{"unshare",
                                       isRoot() ? "-m" : "-rm",
                                       "sh",
                                       "-c",
                                       mountScript(setup),
                                       "sh",
                                       target.string(),
                                       witness.string(),
                                       (tmp.path() / "out.exr").string()};
      wrapped.insert(wrapped.end(), args.begin(), args.end());
      args = wrapped;
    }
  }

  const RunResult r = runWithTimeout(args, c.value("timeout", 120.0));
  ASSERT_FALSE(r.timedOut) << "hang: killed after the time limit";
  if (!witness.empty() && !fs::exists(witness / "mounted") && (setup != "read-only-dir" || isRoot()))
    GTEST_SKIP() << "cannot mount here (" << setup << " needs a private mount namespace): " << r.err;

  EXPECT_EQ(r.status, c.at("status").get<int>()) << r.err;
  const std::vector<std::string> errLines = lines(r.err);
  if (c.contains("stderr")) {
    ASSERT_EQ(errLines.size(), 1u) << r.err;
    const std::string expected = expand(c["stderr"], tmp.path());
    EXPECT_TRUE(matches(errLines[0], expected)) << "got:      " << errLines[0] << "\nexpected: " << expected;
  }
  for (const std::string expected : c.value("stderr_includes", json::array())) {
    const std::string line = expand(expected, tmp.path());
    EXPECT_NE(std::find(errLines.begin(), errLines.end(), line), errLines.end()) << line << "\nin:\n"
                                                                                 << r.err;
  }
  for (const std::string expected : c.value("stdout_includes", json::array()))
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\nin:\n" << r.out;

  if (!witness.empty() && fs::exists(witness / "listing")) {
    // The mount is gone; its contents were copied out.
    EXPECT_EQ(readFile(witness / "out.exr"), kPrecious);
    std::set<std::string> left;
    for (const std::string& name : lines(readFile(witness / "listing"))) left.insert(name);
    left.erase("filler");
    EXPECT_EQ(left, (std::set<std::string>{"out.exr"})) << "a temporary file was left behind";
  } else if (!witness.empty()) {
    EXPECT_EQ(readFile(target / "out.exr"), kPrecious);
    EXPECT_EQ(listing(target), (std::set<std::string>{"out.exr"}));
  }
  if (r.status != 0) {
    EXPECT_EQ(readFile(tmp.path() / "out.exr"), kPrecious);
  }
  // Nothing else was written next to the output (temporary files, partial images).
  std::set<std::string> expected{"out.exr"};
  if (c.contains("generate")) expected.insert(c["generate"]["file"].get<std::string>());
  if (!witness.empty()) {
    for (const std::string& n : listing(tmp.path()))
      if (n.rfind("witness", 0) == 0 || n.rfind(target.filename().string(), 0) == 0) expected.insert(n);
  }
  EXPECT_EQ(listing(tmp.path()), expected);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputs, ::testing::ValuesIn(loadCases()), [](const auto& info) {
  std::string name = info.param.name;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

TEST(BadInputs, CorpusIsLargeAndEveryCaseNamesItsExpectation) {
  const std::vector<Case> cases = loadCases();
  EXPECT_GE(cases.size(), 40u);
  std::set<std::string> names;
  for (const Case& c : cases) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    const bool fails = c.spec.at("status").get<int>() != 0;
    EXPECT_EQ(c.spec.contains("stderr"), fails) << c.name << ": failing cases give their exact message";
    if (!fails) {
      EXPECT_TRUE(c.spec.contains("stderr_includes") || c.spec.contains("stdout_includes"))
          << c.name << ": passing cases name what they print";
    }
  }
}

// The lens cases again through the renderer, once `lensrt render --lens`
// exists: the same status and the same line.
TEST(BadInputs, LensCasesFailTheSameWayInRender) {
  const RunResult help = runWithTimeout({LENSRT_BINARY, "render", "--help"}, 60);
  if (help.out.find("--lens") == std::string::npos) GTEST_SKIP() << "lensrt render has no --lens option yet";
  int checked = 0;
  for (const Case& c : loadCases()) {
    if (!c.spec.contains("lens") || c.spec.at("status").get<int>() == 0) continue;
    if (c.spec.contains("render_known_issue")) {
      std::cout << "[ KNOWN    ] " << c.name << ": " << c.spec["render_known_issue"].get<std::string>()
                << "\n";
      continue;
    }
    const TempDir tmp(c.name);
    writeFile(tmp.path() / "out.exr", kPrecious);
    if (c.spec.contains("generate")) {
      const json& g = c.spec["generate"];
      std::ofstream out(tmp.path() / g.at("file").get<std::string>(), std::ios::binary);
      for (int i = 0; i < g.at("count").get<int>(); ++i) out << g.at("line").get<std::string>();
    }
    const RunResult r =
        runWithTimeout({LENSRT_BINARY, "render", (kInputs / "good-triangle.gltf").string(), "--camera",
                        "lens", "--lens", expand(c.spec["lens"], tmp.path()), "--res", "8x8", "--spp", "1",
                        "-q", "-o", (tmp.path() / "out.exr").string()},
                       120);
    ASSERT_FALSE(r.timedOut) << c.name;
    EXPECT_EQ(r.status, c.spec.at("status").get<int>()) << c.name << ": " << r.err;
    EXPECT_EQ(lines(r.err), std::vector<std::string>{expand(c.spec["stderr"], tmp.path())}) << c.name;
    EXPECT_EQ(readFile(tmp.path() / "out.exr"), kPrecious) << c.name;
    ++checked;
  }
  EXPECT_GT(checked, 15);
}

}  // namespace
}  // namespace lensrt::robustness
