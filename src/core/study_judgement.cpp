#include "gradfric/core/study_judgement.hpp"

#include "gradfric/core/format.hpp"

#include <cmath>
#include <cstdio>

namespace gradfric::study {

namespace {

// "+-0.77" or "n/b" (not bounded).
std::string bar(const verification::Verdict& v) {
  return v.bounded() ? formatNumber("%.2g", 100 * v.relative()) : std::string("n/b");
}

}  // namespace

std::string judgementMarkdown(const std::vector<StudyRow>& rows) {
  std::string text =
      "| observable | scene | meshes | values | convergence | p | error fit | Fs | phi_0 | U of each mesh [%] |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  int alone = 0;
  for (const auto& ladder : ladders(rows)) {
    if (ladder.size() < 3) {
      alone += int(ladder.size());
      continue;
    }
    std::string meshes, values, bars;
    verification::Verdict finest;
    for (std::size_t k = 0; k < ladder.size(); ++k) {
      const verification::Verdict v = judgeLadder(ladder, int(k));
      const char* sep = k ? ", " : "";
      meshes += sep + meshText(ladder[k]->mesh);
      values += sep + formatNumber("%.6f", ladder[k]->value);
      bars += sep + bar(v);
      finest = v;
    }
    const bool bounded = finest.bounded();
    text += "| " + ladder[0]->observable + " | " + sceneText(ladder[0]->scene) + " | " + meshes + " | " + values + " | " +
            verification::toString(finest.convergence) + " | " +
            (finest.order != 0 ? formatNumber("%.2f", finest.order) : std::string("")) + " | " +
            (bounded ? verification::toString(finest.fit) : "") + " | " +
            (bounded ? formatNumber("%.3g", finest.safetyFactor) : std::string("")) + " | " +
            (bounded ? formatNumber("%.6f", finest.extrapolated) : std::string("")) + " | " + bars + " |\n";
  }
  text += "\n" + std::to_string(alone) +
          " rows make no ladder of three meshes of one scene and shape (single settings such as a time step or "
          "a contact method, and ladders still being measured): they give no bar.\n";
  return text;
}

std::string pointBarLines(const std::vector<StudyBar>& muStatic, const std::vector<StudyBar>& muKinetic) {
  std::string text;
  for (std::size_t p = 0; p < muStatic.size(); ++p)
    for (const auto* bars : {&muStatic, &muKinetic})
      text += "  bar point " + std::to_string(p) + (bars == &muStatic ? " mu_s: " : " mu_k: ") +
              describeBar((*bars)[p]) + "\n";
  return text;
}

std::string judgementTsv(const std::vector<StudyRow>& rows) {
  std::string text =
      "observable\tscene\tmesh\tvalue\tmembers\tconvergence\torder\tfit\tsafety_factor\textrapolated\tfit_std_dev\t"
      "data_range\thalf_width\tuncertainty\trelative_uncertainty\n";
  for (const auto& ladder : ladders(rows))
    for (std::size_t k = 0; k < ladder.size(); ++k) {
      const verification::Verdict v = judgeLadder(ladder, int(k));
      text += ladder[k]->observable + "\t" + sceneText(ladder[k]->scene) + "\t" + meshText(ladder[k]->mesh) + "\t" +
              formatNumber("%.6f", ladder[k]->value) + "\t" + std::to_string(ladder.size()) + "\t" +
              verification::toString(v.convergence) + "\t" + formatNumber("%.6g", v.order) + "\t" +
              verification::toString(v.fit) + "\t" + formatNumber("%.6g", v.safetyFactor) + "\t" +
              formatNumber("%.9g", v.extrapolated) + "\t" + formatNumber("%.6g", v.fitStdDev) + "\t" + formatNumber("%.6g", v.dataRange) +
              "\t" + formatNumber("%.6g", v.halfWidth) + "\t" + formatNumber("%.6g", v.bounded() ? v.uncertainty : NAN) + "\t" +
              formatNumber("%.6g", v.bounded() ? v.relative() : NAN) + "\n";
    }
  return text;
}

}  // namespace gradfric::study
