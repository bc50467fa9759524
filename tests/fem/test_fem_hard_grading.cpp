// FEM hard cases, grading: |Delta| = 0.9 for E, for the friction coefficients and for both,
// linear and triangular, both signs; each at the default step (0.9 of the stable step) and at half of
// it, on 16 x 16 x 2 hexahedra. Checks and their tolerances: fem_hard_cases.hpp.
#include "fem_hard_cases.hpp"

using namespace gradfric;
using namespace gradfric::fem;
using namespace gradfric::fem::test;

namespace {

std::vector<HardCase> gradingCases() {
  std::vector<HardCase> cases;
  const std::pair<GradedProperty, const char*> properties[] = {
      {GradedProperty::YoungsModulus, "E"}, {GradedProperty::Friction, "friction"}, {GradedProperty::Both, "both"}};
  const std::pair<GradingProfile, const char*> profiles[] = {{GradingProfile::Linear, "linear"},
                                                            {GradingProfile::Triangular, "triangular"}};
  for (const auto& [property, pname] : properties)
    for (const auto& [profile, fname] : profiles)
      for (double delta : {0.9, -0.9}) {
        HardCase c;
        c.name = std::string(pname) + "_" + fname + (delta > 0 ? "_plus" : "_minus") + "0.9";
        c.setup = [property = property, profile = profile, delta](FemParameters& q, Grading& g) {
          // A band at 0.1 E0 loads ~10 x slower than Eq. 2 says for E0: give the run time to
          // find the peak and finish the kinetic window (it stops as soon as both are known).
          q.slideTime = 12 * q.eq2PeakTime();  // 8 t_load left E triangular -0.9's mu_k window open with the state law
          g.profile = profile;
          g.property = property;
          g.delta = delta;
          g.bands = 10;
        };
        // E graded by 0.9 (bands down to 0.1 E0), except the triangular minus profile: the soft
        // band shears elastically over its bottom nodes, which stay stuck (E linear +0.9: 34 of 289
        // nodes never slipped in 8 t_load), so the shared peak rule (every site slipped) never
        // confirms the peak. The FEM's former rule (mu below 95 % of its maximum) did, at mu_s
        // 0.5687 (E linear +0.9).
        if (property == GradedProperty::YoungsModulus && !(profile == GradingProfile::Triangular && delta < 0))
          c.peakConfirms = false;
        // mu_k: with the default damping of the sliding plate (from the confirmed peak) mu(t) after
        // the peak of these |Delta| = 0.9 plates is a node-scale stick-slip whose window mean
        // converges more slowly in dt than the undamped ringing did: measured dt vs dt/2 up to
        // 7.4 % (both linear -0.9; E triangular -0.9 7.3 %; friction triangular -0.9 6.4 %).
        c.muKTolerance = 0.08;
        if (property != GradedProperty::YoungsModulus) {
          // With local mu_s down to 0.1 on one side, mu(t) after the first slip is a fast, undamped
          // oscillation (hundreds of local maxima within 10 % of the peak) and mu_s is the largest
          // of them: it converges in dt at second order but with a large constant. Measured on
          // friction linear +0.9, 16 x 16 x 2: mu_s 0.6693 / 0.6275 / 0.6166 at dt_safety 0.6 /
          // 0.3 / 0.15 (6.7 %, then 1.7 %: ratio 3.8, second order). These cases therefore run at
          // 0.3 (and 0.15) and must agree within 4 % (measured: up to 3.0 %, friction triangular +0.9);
          // the E-graded ones meet 1 % at the default.
          c.muSTolerance = 0.04;
          c.setup = [inner = c.setup](FemParameters& q, Grading& g) {
            inner(q, g);
            q.dtSafety = 0.3;
          };
        }
        cases.push_back(c);
      }
  return cases;
}

class FemHardGrading : public ::testing::TestWithParam<HardCase> {};

TEST_P(FemHardGrading, StableBoundedPhysicalAndConvergedInDt) { checkHardCase(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Delta09, FemHardGrading, ::testing::ValuesIn(gradingCases()),
                         [](const ::testing::TestParamInfo<HardCase>& info) {
                           std::string n = info.param.name;
                           std::replace(n.begin(), n.end(), '.', '_');
                           return n;
                         });

}  // namespace
