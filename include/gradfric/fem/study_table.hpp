#pragma once
// The rows of the FEM's convergence studies, as the error bars read them: docs/fem_study.tsv (mu_s
// of mu_s-only runs) and docs/fem_study_kinetic.tsv (mu_k of full runs, with the spread of the
// kinetic window's batch means). Both are embedded at build time (fem_study_data.hpp, generated).
// PETSc-free.
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

struct StudyRow {
  std::string law, property, element, contact;
  double slipLength = 0, delta = 0, dtSafety = 0;
  double mu = 0;      // mu_s (fem_study.tsv) or mu_k (fem_study_kinetic.tsv)
  double spread = 0;  // mu_k only: (max - min) / mean of the window's batch means
  int n = 0, nz = 0;
  double edgeRatio = 1, edgeBand = 0;  // the mesh's edge grading (edge_grading.hpp; ratio 1: uniform)
  NormalStressFilter filter;           // the contact column's ",pc=L/V*" (off without it)
};

enum class StudyColumns { StaticOnly, KineticWithSpread };

// The rows of a table's text; a row that does not read is an error naming the table and the line.
std::vector<StudyRow> parseStudyTable(const std::string& text, StudyColumns columns = StudyColumns::StaticOnly);

// The grading as the tables name it: "none", "E" or "friction".
std::string studiedPropertyName(const Grading& grading);

// Whether the row ran on a mesh graded as `edge` (uniform: ratio 1).
bool sameEdgeGrading(const StudyRow& row, const EdgeGrading& edge);

// Whether the row ran the run's law and D_c, element, the given plate, in-plane n and nz, dt
// safety, contact method ("penalty", "kinematic"), edge grading and normal-stress filter.
bool studyRowMatches(const StudyRow& row, const FemParameters& q, const std::string& property, double delta, int n,
                     int nz, double dtSafety, const char* contact, const EdgeGrading& edge,
                     const NormalStressFilter& filter);

// The first row that matches those settings (nullptr: the study did not run them).
const StudyRow* findStudyRow(const std::vector<StudyRow>& rows, const FemParameters& q, const std::string& property,
                             double delta, int n, int nz, double dtSafety, const char* contact, const EdgeGrading& edge,
                             const NormalStressFilter& filter);

// The rows of the mesh ladder whose coarsest mesh is n x n x nz, refined in every direction
// (2n x 2n x 2nz, 4n x 4n x 4nz) or in-plane (2n, 4n at nz), into m; false where a rung is missing.
bool findMeshLadder(const std::vector<StudyRow>& rows, const FemParameters& q, const std::string& property,
                    double delta, int n, int nz, bool allDirections, double dtSafety, const char* contact,
                    const EdgeGrading& edge, const NormalStressFilter& filter, const StudyRow* (&m)[3]);

// That ladder's meshes as the bases print them: "50x50x5/100x100x10/200x200x20" or "50x50/100/200 x 5".
std::string ladderMeshes(int n, int nz, bool allDirections);

// Two decimals; below 0.1 % two significant digits, so a small term is not printed as 0.00 %.
std::string percentText(double fraction);

}  // namespace gradfric::fem
