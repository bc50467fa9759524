#pragma once
// The measurements of a convergence study (docs/fem_study.tsv, docs/sbm_study.tsv), read at run
// time, and the bar they prove for a run: the run gets the verdict of the ladder holding its own
// discretisation, judged alone by the one procedure (core/verification.hpp), or "not measured"
// with the reason. A row is one result: observable, mesh (nx x ny x nz, or the lattice's N_b),
// value with its standard error, and the scene, the settings that differ from the defaults. A
// ladder is the rows of one observable and one scene whose meshes are one shape refined in every
// direction (the explicit step follows the cell size, so space and time refine together).
// PETSc-free.
#include "gradfric/core/verification.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gradfric::study {

// name (option without its dash) and value, sorted by name; empty: every setting at its default.
using SceneKey = std::vector<std::pair<std::string, std::string>>;

struct StudyRow {
  std::string observable;  // mu_s, mu_k
  std::vector<int> mesh;   // {nx, ny, nz} or {N_b}
  double value = 0, stdError = 0;
  int samples = 0;  // realisations (or batches) behind stdError
  SceneKey scene;
};

// The rows of a table's text ('#' lines are comments); a row that does not read throws
// std::invalid_argument naming the table and the line.
std::vector<StudyRow> parseStudyTable(const std::string& text, const std::string& tableName);
// "a=1,b=x" (or "-") as a sorted key, and back.
SceneKey parseSceneKey(const std::string& text);
std::string sceneText(const SceneKey& key);
// "100x100x10" or "120".
std::string meshText(const std::vector<int>& mesh);

// The table file `name` (fem_study.tsv, sbm_study.tsv): $GRADFRIC_STUDY_DIR if set; an installed
// driver's <prefix>/share/gradfric; a build tree's source docs/. Throws std::runtime_error naming
// where it looked.
std::string studyTablePath(const std::string& name);
// The rows of that file, read once per process.
const std::vector<StudyRow>& studyTable(const std::string& name);

// Whether two settings' values are one: equal as numbers (relative 1e-9) or as text.
bool sameSettingValue(const std::string& a, const std::string& b);
// Whether two scenes are one: the same names with the same values.
bool sameScene(const SceneKey& a, const SceneKey& b);

struct StudyBar {
  bool judged = false;                  // the run's mesh is a member of its scene's ladder: verdict holds
  bool measured = false;
  std::string why;                      // not measured: the reason
  std::vector<const StudyRow*> ladder;  // the rows of the run's scene and mesh shape
  verification::Verdict verdict;
  // The rows a derived ladder points into (variationBar), shared by the bar's copies.
  std::shared_ptr<const std::vector<StudyRow>> derivedRows;
};

// The bar of a run of `scene` on `mesh` for `observable` from the rows.
StudyBar studyBar(const std::vector<StudyRow>& rows, const std::string& observable, const SceneKey& scene,
                  const std::vector<int>& mesh);

// The bar of the relative variation phi / phi_0 - 1 of `scene` against `reference` (its plate
// without the grading) on `mesh`: the ladder of that ratio on the meshes both scenes hold, judged
// by the same procedure. Deterministic rows only: the ratio of two ensembles' means has no row's
// standard error, so a stochastic row leaves it not measured, said so.
StudyBar variationBar(const std::vector<StudyRow>& rows, const std::string& observable, const SceneKey& scene,
                      const SceneKey& reference, const std::vector<int>& mesh);
StudyBar variationBar(const std::string& table, const std::string& observable, const SceneKey& scene,
                      const SceneKey& reference, const std::vector<int>& mesh);

// For people, from the fields: "+- 0.77 % (monotone, observed order 1.69, Fs 1.25; ladder 50x50x5
// 0.950239, ...)" or "not measured: <why>".
std::string describeBar(const StudyBar& bar);
// The ladder's members as "50x50x5:0.950239 100x100x10:0.937429 ..." (stored with the bar).
std::string ladderText(const StudyBar& bar);

// The same from the table file `table` (studyTable); a table that is not found gives "not measured"
// naming where it was looked for.
StudyBar studyBar(const std::string& table, const std::string& observable, const SceneKey& scene,
                  const std::vector<int>& mesh);

// Every ladder of a table (rows grouped by observable, scene and mesh shape, coarse to fine), for
// gradfric-study -judge.
std::vector<std::vector<const StudyRow*>> ladders(const std::vector<StudyRow>& rows);
// The verdict on a ladder's member (h = 1 / mesh[0]; formal order 2).
verification::Verdict judgeLadder(const std::vector<const StudyRow*>& ladder, int member);

}  // namespace gradfric::study
