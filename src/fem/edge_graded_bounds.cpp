#include "gradfric/fem/edge_graded_bounds.hpp"

#include "gradfric/core/refinement_ladder.hpp"
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/ladder_term.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gradfric::fem {

std::vector<GradedLadder> edgeGradedLadders(const std::vector<StudyRow>& rows, const FemParameters& q,
                                            const Grading& g) {
  std::vector<GradedLadder> found;
  const StudySettings run = meshStudySettings(q, g);
  for (const StudyRow& r : rows) {  // r: the coarsest mesh of a graded ladder
    StudySettings s = run;  // the run's settings on this row's edge grading
    s.edge = {r.edgeRatio, r.edgeBand};
    if (r.edgeRatio == 1.0 || !studyRowMatches(r, q, s, r.n, r.nz)) continue;
    const StudyRow* m[3];
    if (!findMeshLadder(rows, q, s, r.n, r.nz, true, m) || findStudyRow(rows, q, s, 8 * r.n, 8 * r.nz))
      continue;  // not a complete ladder, or not the grading's finest
    char name[200];
    std::snprintf(name, sizeof name, "%s edge-graded (ratio %g, band %g m), all directions",
                  ladderMeshes(r.n, r.nz, true).c_str(), r.edgeRatio, r.edgeBand);
    found.push_back({m[2], ladderTerm("mesh", name, m, 2)});
  }
  return found;
}

// Of several graded families, the smallest bound. The graded finest mesh must have no in-plane cell
// wider than the run's and no fewer layers, so its bound covers the run's thickness error too.
ErrorTerm throughEdgeGradedLadder(const StudyRow& run, const std::vector<GradedLadder>& ladders,
                                  const FemParameters& q) {
  ErrorTerm best{false, 0, ""};
  for (const GradedLadder& ladder : ladders) {
    if (!ladder.term.measured) continue;
    const StudyRow& f = *ladder.finest;
    const MeshAxis axis = makeMeshAxis(EdgeGrading{f.edgeRatio, f.edgeBand}, f.n, q.plate.length);
    const double widest = *std::max_element(axis.classWidth.begin(), axis.classWidth.end());
    if (widest > q.plate.length / run.n * (1 + 1e-9) || f.nz < run.nz) continue;
    const double bound = boundThroughFinerValue({run.mu}, {f.mu}, ladder.term.relative);
    if (best.measured && bound >= best.relative) continue;
    char text[200];
    std::snprintf(text, sizeof text, "; the run %.6f bounded through its finest value %.6f (nowhere coarser than "
                  "the run's mesh): |difference| %s + its bound %s",
                  run.mu, f.mu, percentText(std::fabs(run.mu - f.mu) / std::fabs(f.mu)).c_str(),
                  percentText(ladder.term.relative).c_str());
    best = {true, bound, ladder.term.basis + text, q.normalFilter.active()};
  }
  return best;
}

std::string refutedByEdgeGradedLadder(const StudyRow& run, const std::vector<GradedLadder>& ladders,
                                      const ErrorTerm& mesh) {
  for (const GradedLadder& ladder : ladders) {
    if (!ladder.term.measured) continue;
    const BoundedValue values[2] = {{run.mu, mesh.relative}, {ladder.finest->mu, ladder.term.relative}};
    if (shareALimit(values, 2)) continue;
    char text[200];
    std::snprintf(text, sizeof text, "; refuted: the run's %.6f +- %s and the edge-graded %dx%dx%d's %.6f +- %s share "
                  "no limit", run.mu, percentText(mesh.relative).c_str(), ladder.finest->n, ladder.finest->n,
                  ladder.finest->nz, ladder.finest->mu, percentText(ladder.term.relative).c_str());
    return mesh.basis + text;
  }
  return "";
}

}  // namespace gradfric::fem
