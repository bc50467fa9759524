// The spring-block scene's resume and extension checks: the campaign's file check
// (campaign/resume_check.hpp) with what an extension may change (the count, the target, the
// swept lists) and how its points and realisations must lie in the file.
#include "gradfric/campaign/resume_check.hpp"
#include "gradfric/ensemble/scene_file.hpp"

#include <set>
#include <string>

namespace gradfric::ensemble {

namespace {

// What an extension may change: the count (or the target) and the swept lists.
bool extensionMayChange(const std::string& name) {
  static const std::set<std::string> names = {
      "ensemble_realisations", "ensemble_delta",       "ensemble_theta",      "ensemble_sigma",
      "ensemble_property",     "ensemble_profile",     "ensemble_target",     "ensemble_target_type",
      "ensemble_target_min",   "ensemble_target_max"};
  return names.count(name) > 0;
}

// Extension: the file's points are the first points of the scene's sweep, in order, and its
// realisations the first of each point. "" if so.
std::string extensionMismatch(const Scene& scene, const io::ResultsFile& file) {
  const auto& l = file.layout();
  if (l.points > scene.points())
    return "it has " + std::to_string(l.points) + " sweep points, the scene " + std::to_string(scene.points()) +
           " (an extension adds points, never removes them)";
  if (l.realisations > scene.realisations)
    return "it has " + std::to_string(l.realisations) + " realisations per point, the scene " +
           std::to_string(scene.realisations) + " (an extension adds realisations, never removes them)";
  const io::SweepTable& old = file.sweep();
  const io::SweepTable& now = scene.table;
  for (int p = 0; p < l.points; ++p)
    if (old.delta[p] != now.delta[p] || old.theta[p] != now.theta[p] || old.sigma[p] != now.sigma[p] ||
        old.sigmaKinetic[p] != now.sigmaKinetic[p] || old.property[p] != now.property[p] ||
        old.profile[p] != now.profile[p])
      return "its point " + std::to_string(p) + " is not point " + std::to_string(p) +
             " of the scene's sweep (the file's points must come first, in order: append values to the outermost "
             "swept list)";
  return "";
}

campaign::ResumeTarget targetOf(const Scene& scene) {
  return campaign::ResumeTarget{scene.sceneAttributes, scene.layout, "-resume", "-output_overwrite"};
}

}  // namespace

void checkResumable(MPI_Comm comm, const Scene& scene, const std::string& path) {
  campaign::checkResumable(comm, targetOf(scene), path);
}

void checkExtendable(MPI_Comm comm, const Scene& scene, const std::string& path) {
  campaign::Extension extension;
  extension.mayChange = extensionMayChange;
  extension.mismatch = [&scene](const io::ResultsFile& file) { return extensionMismatch(scene, file); };
  campaign::checkExtendable(comm, targetOf(scene), extension, path);
}

}  // namespace gradfric::ensemble
