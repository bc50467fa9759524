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

// The plate as the tables name it: the graded property ("none", "E" or "friction") and Delta. A
// profile other than linear and a sliding angle other than 0 follow the property after commas, as
// the filter follows the contact: "E,triangular", "friction,theta=90", "E,triangular,theta=90".
struct StudiedPlate {
  std::string property = "none";
  double delta = 0;
};
StudiedPlate studiedPlate(const Grading& grading, double slidingAngleDegrees);

// What a row ran besides the run's law, D_c and element and besides its mesh size.
struct StudySettings {
  StudiedPlate plate;
  double dtSafety = 0.6;            // dt / stable step
  std::string contact = "penalty";  // "penalty" or "kinematic"
  EdgeGrading edge;                 // ratio 1: uniform
  NormalStressFilter filter;        // off: none
};

// The run's plate, edge grading and filter, at dt safety 0.6 and the penalty contact (the settings of
// the mu_s study's mesh ladders).
StudySettings meshStudySettings(const FemParameters& q, const Grading& grading);

// Whether the row ran the run's law, D_c and element with these settings on n x n x nz.
bool studyRowMatches(const StudyRow& row, const FemParameters& q, const StudySettings& s, int n, int nz);

// The first row that matches (nullptr: the study did not run it).
const StudyRow* findStudyRow(const std::vector<StudyRow>& rows, const FemParameters& q, const StudySettings& s, int n,
                             int nz);

// The rows of the mesh ladder whose coarsest mesh is n x n x nz, refined in every direction
// (2n x 2n x 2nz, 4n x 4n x 4nz) or in-plane (2n, 4n at nz), into m; false where a rung is missing.
bool findMeshLadder(const std::vector<StudyRow>& rows, const FemParameters& q, const StudySettings& s, int n, int nz,
                    bool allDirections, const StudyRow* (&m)[3]);

// That ladder's meshes as the bases print them: "50x50x5/100x100x10/200x200x20" or "50x50/100/200 x 5".
std::string ladderMeshes(int n, int nz, bool allDirections);

// Two decimals; below 0.1 % two significant digits, so a small term is not printed as 0.00 %.
std::string percentText(double fraction);

}  // namespace gradfric::fem
