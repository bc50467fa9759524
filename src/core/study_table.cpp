#include "gradfric/core/study_table.hpp"

#include "gradfric/core/data_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace gradfric::study {

namespace {

std::vector<int> parseMesh(const std::string& text) {
  std::vector<int> mesh;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, 'x')) {
    std::size_t used = 0;
    const int n = std::stoi(part, &used);
    if (used != part.size() || n < 1) throw std::invalid_argument("mesh");
    mesh.push_back(n);
  }
  return mesh;
}

}  // namespace

bool sameSettingValue(const std::string& a, const std::string& b) {
  char* endA = nullptr;
  char* endB = nullptr;
  const double x = std::strtod(a.c_str(), &endA), y = std::strtod(b.c_str(), &endB);
  if (!a.empty() && !b.empty() && *endA == '\0' && *endB == '\0') return sameStudiedValue(x, y);
  return a == b;
}

namespace {

// Whether b is a's shape (every direction refined by one factor).
bool sameShape(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 1; k < a.size(); ++k)
    if (long(a[k]) * b[0] != long(b[k]) * a[0]) return false;
  return true;
}

// The directory of the running executable ("" if unknown).
std::string executableDir() {
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return "";
  std::string exe(path, std::size_t(n));
  return exe.substr(0, exe.find_last_of('/'));
}

bool readable(const std::string& path) { return std::ifstream(path).good(); }

// The settings two scenes do not share (a name missing from one, or another value).
std::size_t differences(const SceneKey& a, const SceneKey& b) {
  const auto missingFrom = [](const SceneKey& x, const SceneKey& y) {
    return std::count_if(x.begin(), x.end(), [&](const auto& s) {
      return std::none_of(y.begin(), y.end(), [&](const auto& t) { return t.first == s.first && sameSettingValue(t.second, s.second); });
    });
  };
  return std::size_t(missingFrom(a, b) + missingFrom(b, a));
}

}  // namespace

SceneKey parseSceneKey(const std::string& text) {
  SceneKey key;
  if (text == "-") return key;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw std::invalid_argument("scene item '" + item + "'");
    key.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  std::sort(key.begin(), key.end());
  return key;
}

std::string sceneText(const SceneKey& key) {
  std::string text;
  for (const auto& [name, value] : key) text += (text.empty() ? "" : ",") + name + "=" + value;
  return text.empty() ? "-" : text;
}

std::string meshText(const std::vector<int>& mesh) {
  std::string text;
  for (int n : mesh) text += (text.empty() ? "" : "x") + std::to_string(n);
  return text;
}

std::vector<StudyRow> parseStudyTable(const std::string& text, const std::string& tableName) {
  std::vector<StudyRow> rows;
  forEachDataRow(text, tableName, [&](std::istringstream& fields) {
    StudyRow r;
    std::string mesh, scene;
    if (!(fields >> r.observable >> mesh >> r.value >> r.stdError >> r.samples >> scene)) return false;
    try {
      r.mesh = parseMesh(mesh);
      r.scene = parseSceneKey(scene);
    } catch (const std::exception&) {
      return false;
    }
    if (r.mesh.empty() || r.stdError < 0 || (r.stdError > 0 && r.samples < 2)) return false;
    for (const StudyRow& earlier : rows)  // one result per observable, scene and mesh: no choosing between two
      if (earlier.observable == r.observable && earlier.mesh == r.mesh && sameScene(earlier.scene, r.scene)) return false;
    rows.push_back(std::move(r));
    return true;
  });
  return rows;
}

std::string studyTablePath(const std::string& name) {
  std::vector<std::string> places;
  if (const char* dir = std::getenv("GRADFRIC_STUDY_DIR")) places.push_back(dir);
  const std::string exe = executableDir();
  if (!exe.empty()) places.push_back(exe + "/../share/gradfric/studies");  // an installed driver
  places.push_back(GRADFRIC_SOURCE_STUDY_DIR);                             // a build tree's source
  std::string looked;
  for (const std::string& dir : places) {
    if (readable(dir + "/" + name)) return dir + "/" + name;
    looked += (looked.empty() ? "" : ", ") + dir;
  }
  throw std::runtime_error("the study table " + name + " was not found (looked in " + looked + ")");
}

const std::vector<StudyRow>& studyTable(const std::string& name) {
  static std::mutex lock;
  static std::map<std::string, std::vector<StudyRow>> read;
  const std::lock_guard<std::mutex> guard(lock);
  const auto at = read.find(name);
  if (at != read.end()) return at->second;
  const std::string path = studyTablePath(name);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return read[name] = parseStudyTable(text.str(), path);
}

bool sameScene(const SceneKey& a, const SceneKey& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].first != b[i].first || !sameSettingValue(a[i].second, b[i].second)) return false;
  return true;
}

verification::Verdict judgeLadder(const std::vector<const StudyRow*>& ladder, int member) {
  std::vector<verification::Member> members;
  for (const StudyRow* r : ladder) members.push_back({1.0 / r->mesh[0], r->value, r->stdError, r->samples});
  return verification::judge(members, member);
}

StudyBar studyBar(const std::vector<StudyRow>& rows, const std::string& observable, const SceneKey& scene,
                  const std::vector<int>& mesh) {
  StudyBar bar;
  const StudyRow* nearest = nullptr;  // of the observable's scenes, the one differing in the fewest settings
  std::size_t fewest = SIZE_MAX;
  std::string otherShapes;  // the meshes of the run's scene in other shapes
  for (const StudyRow& r : rows) {
    if (r.observable != observable) continue;
    if (sameScene(r.scene, scene)) {
      if (sameShape(r.mesh, mesh))
        bar.ladder.push_back(&r);
      else
        otherShapes += (otherShapes.empty() ? "" : ", ") + meshText(r.mesh);
      continue;
    }
    const std::size_t differing = differences(r.scene, scene);
    if (differing < fewest) fewest = differing, nearest = &r;
  }
  std::sort(bar.ladder.begin(), bar.ladder.end(), [](const StudyRow* a, const StudyRow* b) { return a->mesh[0] < b->mesh[0]; });
  const auto at = std::find_if(bar.ladder.begin(), bar.ladder.end(), [&](const StudyRow* r) { return r->mesh == mesh; });
  if (bar.ladder.empty() && !otherShapes.empty()) {
    bar.why = "the study holds no mesh of the shape of " + meshText(mesh) + " refined in every direction for this scene (" +
              "its meshes: " + otherShapes + ")";
    return bar;
  }
  if (bar.ladder.empty()) {
    bar.why = "no " + observable + " row of the study has this scene (" + sceneText(scene) + ")" +
              (nearest ? "; the nearest studied scene is " + sceneText(nearest->scene) : "");
    return bar;
  }
  std::string meshes;
  for (const StudyRow* r : bar.ladder) meshes += (meshes.empty() ? "" : ", ") + meshText(r->mesh);
  if (at == bar.ladder.end()) {
    bar.why = "mesh " + meshText(mesh) + " is not in the study's ladder of this scene (" + meshes + ")";
    return bar;
  }
  bar.verdict = judgeLadder(bar.ladder, int(at - bar.ladder.begin()));
  bar.judged = true;
  bar.measured = bar.verdict.bounded();
  if (bar.verdict.convergence == verification::Convergence::TooFewMembers)
    bar.why = "the study's ladder of this scene holds " + std::to_string(bar.ladder.size()) + " mesh(es) (" + meshes +
              "); the procedure needs 3";
  else if (!bar.measured)
    bar.why = std::string(verification::toString(bar.verdict.convergence)) + " on " + meshes;
  return bar;
}

namespace {

// The bar `judge` gives from the rows of the table file `table`; a table that is not found gives
// "not measured" naming where it was looked for.
template <class Judge>
StudyBar fromTable(const std::string& table, Judge&& judge) {
  try {
    return judge(studyTable(table));
  } catch (const std::runtime_error& e) {
    StudyBar bar;
    bar.why = e.what();
    return bar;
  }
}

}  // namespace

StudyBar studyBar(const std::string& table, const std::string& observable, const SceneKey& scene,
                  const std::vector<int>& mesh) {
  return fromTable(table, [&](const std::vector<StudyRow>& rows) { return studyBar(rows, observable, scene, mesh); });
}

StudyBar variationBar(const std::vector<StudyRow>& rows, const std::string& observable, const SceneKey& scene,
                      const SceneKey& reference, const std::vector<int>& mesh) {
  auto derived = std::make_shared<std::vector<StudyRow>>();
  for (const StudyRow& r : rows) {
    if (r.observable != observable || !sameScene(r.scene, scene)) continue;
    const auto base = std::find_if(rows.begin(), rows.end(), [&](const StudyRow& b) {
      return b.observable == observable && b.mesh == r.mesh && sameScene(b.scene, reference);
    });
    if (base == rows.end()) continue;  // a mesh the plate without the grading was not run on
    if (r.stdError != 0 || base->stdError != 0) {
      StudyBar bar;
      bar.why = "the study's rows of this scene are ensembles (" + meshText(r.mesh) +
                "): a ratio of two means has no row's standard error to judge its ladder by";
      return bar;
    }
    StudyRow v = r;
    v.value = r.value / base->value - 1.0;
    derived->push_back(v);
  }
  if (derived->empty()) {  // the reason: the scene's own (no rows, another shape), or its reference's
    const StudyBar own = studyBar(rows, observable, scene, mesh);
    StudyBar bar;
    bar.why = own.ladder.empty() ? own.why
                                 : "the study holds none of this scene's meshes for the plate without the grading (" +
                                       sceneText(reference) + ")";
    return bar;
  }
  StudyBar bar = studyBar(*derived, observable, scene, mesh);
  bar.derivedRows = std::move(derived);  // the ladder points into it
  return bar;
}

StudyBar variationBar(const std::string& table, const std::string& observable, const SceneKey& scene,
                      const SceneKey& reference, const std::vector<int>& mesh) {
  return fromTable(table, [&](const std::vector<StudyRow>& rows) {
    return variationBar(rows, observable, scene, reference, mesh);
  });
}

std::string ladderText(const StudyBar& bar) {
  std::string text;
  char value[32];
  for (const StudyRow* r : bar.ladder) {
    std::snprintf(value, sizeof value, ":%.6f", r->value);
    text += (text.empty() ? "" : " ") + meshText(r->mesh) + value;
  }
  return text;
}

std::string describeBar(const StudyBar& bar) {
  if (!bar.measured) return "not measured: " + bar.why;
  const verification::Verdict& v = bar.verdict;
  char text[160];
  if (v.fit == verification::ErrorFit::ObservedOrder)
    std::snprintf(text, sizeof text, "+- %.2g %% (%s, observed order %.2f, Fs %.3g", 100 * v.relative(),
                  verification::toString(v.convergence), v.order, v.safetyFactor);
  else
    std::snprintf(text, sizeof text, "+- %.2g %% (%s, %s, Fs %.3g", 100 * v.relative(),
                  verification::toString(v.convergence), verification::toString(v.fit), v.safetyFactor);
  return text + std::string("; ladder ") + ladderText(bar) + ")";
}

std::vector<std::vector<const StudyRow*>> ladders(const std::vector<StudyRow>& rows) {
  std::vector<std::vector<const StudyRow*>> found;
  for (const StudyRow& r : rows) {
    const auto same = [&](const std::vector<const StudyRow*>& l) {
      return l[0]->observable == r.observable && sameScene(l[0]->scene, r.scene) && sameShape(l[0]->mesh, r.mesh);
    };
    const auto at = std::find_if(found.begin(), found.end(), same);
    if (at == found.end())
      found.push_back({&r});
    else
      at->push_back(&r);
  }
  for (auto& l : found)
    std::sort(l.begin(), l.end(), [](const StudyRow* a, const StudyRow* b) { return a->mesh[0] < b->mesh[0]; });
  return found;
}

}  // namespace gradfric::study
