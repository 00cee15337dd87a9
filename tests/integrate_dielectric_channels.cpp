// The glass columns asked for one channel (DielectricChannels, integrate/dielectric_albedo.h and
// dielectric_albedo_avg.h): E_R alone or E_T alone must have exactly the bits of that channel of
// the both-channel column, charge fewer evaluations (the two channels' counts adding up to the
// both-channel count), and the memos must hand a channel an entry lacks only after computing it.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/models/roughness.h"

using namespace kiln;

namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

const double kEtas[] = {1.1, 1.33, 1.5, 2.2, 3.0};
constexpr int kN = 5;

/// The one-channel columns onlyR and onlyT hold both's bits of their channel and NaN in the
/// other, and their evaluations (evR, evT) are each fewer than both's (evBoth) and add up to it.
void RequireChannelsOfBoth(const std::array<double, 2>* both, const std::array<double, 2>* onlyR,
                           const std::array<double, 2>* onlyT, long long evBoth, long long evR,
                           long long evT) {
  for (int e = 0; e < kN; ++e) {
    INFO("eta " << kEtas[e]);
    CHECK(SameBits(onlyR[e][0], both[e][0]));
    CHECK(SameBits(onlyT[e][1], both[e][1]));
    CHECK(std::isnan(onlyR[e][1]));
    CHECK(std::isnan(onlyT[e][0]));
  }
  CHECK(evR > 0);
  CHECK(evT > 0);
  CHECK(evR < evBoth);
  CHECK(evT < evBoth);
  CHECK(evR + evT == evBoth);
}

}  // namespace

TEST_CASE(
    "an E column asked for one channel gives that channel's bits of both, for fewer "
    "evaluations",
    "[dielectric][glass-rule]") {
  for (double mu : {0.0, 0.05, 0.5, 1.0})
    for (double r : {1e-3, 0.4, 1.0}) {
      INFO("mu " << mu << " r " << r);
      const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
      std::array<double, 2> both[kN], onlyR[kN], onlyT[kN];
      long long evBoth = 0, evR = 0, evT = 0;
      const DielectricRuleOptions opt = TunedDielectricRuleOptions();
      FixedRuleDielectricAlbedoColumn(mu, alpha, kEtas, kN, opt, both, &evBoth);
      FixedRuleDielectricAlbedoColumn(mu, alpha, kEtas, kN, opt, onlyR, &evR,
                                      DielectricChannels::R);
      FixedRuleDielectricAlbedoColumn(mu, alpha, kEtas, kN, opt, onlyT, &evT,
                                      DielectricChannels::T);
      RequireChannelsOfBoth(both, onlyR, onlyT, evBoth, evR, evT);
    }
}

TEST_CASE(
    "an average column asked for one channel gives that channel's bits of both, for fewer "
    "evaluations, and its memo computes a channel an entry lacks",
    "[dielectric][glass-rule]") {
  // A roughness no other test asks for: the memos start without it.
  const double alpha = 0.0731;
  std::array<double, 2> both[kN], onlyR[kN], onlyT[kN];
  long long evBoth = 0, evR = 0, evT = 0;
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, kDielectricAverageNodes, both, &evBoth);
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, kDielectricAverageNodes, onlyR, &evR,
                                         DielectricChannels::R);
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, kDielectricAverageNodes, onlyT, &evT,
                                         DielectricChannels::T);
  RequireChannelsOfBoth(both, onlyR, onlyT, evBoth, evR, evT);

  // The remembering column: E_avg_R first (the entry holds R only), then E_avg_T (computed and
  // added), then both (read): each the bits and the evaluations of computing what it asks.
  std::array<double, 2> got[kN];
  long long ev = 0;
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, got, &ev, DielectricChannels::R);
  CHECK(ev == evR);
  for (int e = 0; e < kN; ++e) CHECK((SameBits(got[e][0], both[e][0]) && std::isnan(got[e][1])));
  ev = 0;
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, got, &ev, DielectricChannels::T);
  CHECK(ev == evT);
  for (int e = 0; e < kN; ++e) CHECK((SameBits(got[e][1], both[e][1]) && std::isnan(got[e][0])));
  ev = 0;
  FixedRuleDielectricAlbedoAverageColumn(alpha, kEtas, kN, got, &ev, DielectricChannels::Both);
  CHECK(ev == evBoth);
  for (int e = 0; e < kN; ++e)
    CHECK((SameBits(got[e][0], both[e][0]) && SameBits(got[e][1], both[e][1])));
}

TEST_CASE("the search's points prepared for one channel are integrated again for the other only",
          "[dielectric][glass-rule]") {
  const double alpha = 0.1713;  // no other test's roughness
  const double etas[] = {1.2, 1.7, 2.6};
  std::array<double, 2> both[3];
  long long evBoth = 0, evR = 0, evT = 0;
  std::array<double, 2> tmp[3];
  FixedRuleDielectricAlbedoAverageColumn(alpha, etas, 3, kDielectricAverageNodes, both, &evBoth);
  FixedRuleDielectricAlbedoAverageColumn(alpha, etas, 3, kDielectricAverageNodes, tmp, &evR,
                                         DielectricChannels::R);
  FixedRuleDielectricAlbedoAverageColumn(alpha, etas, 3, kDielectricAverageNodes, tmp, &evT,
                                         DielectricChannels::T);
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3, DielectricChannels::R) == 3);
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3, DielectricChannels::R) == 0);
  for (int e = 0; e < 3; ++e) {
    INFO("eta " << etas[e]);
    long long ev = 0;
    const std::array<double, 2> r =
        FixedRuleDielectricAlbedoAverage(alpha, etas[e], &ev, DielectricChannels::R);
    CHECK(SameBits(r[0], both[e][0]));
    CHECK(ev == evR);
  }
  // E_T is not held: asked for it, the points are integrated for E_T alone.
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3, DielectricChannels::T) == 3);
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3, DielectricChannels::Both) == 0);
  for (int e = 0; e < 3; ++e) {
    INFO("eta " << etas[e]);
    long long ev = 0, evExit = 0;
    const std::array<double, 2> b = FixedRuleDielectricAlbedoAverage(alpha, etas[e], &ev);
    CHECK(SameBits(b[0], both[e][0]));
    CHECK(SameBits(b[1], both[e][1]));
    CHECK(ev == evBoth);
    const double exitT =
        FixedRuleDielectricExitAverageT(alpha, 1 / etas[e], kDielectricAverageNodes, &evExit);
    const double eta = 1 / etas[e];
    CHECK(SameBits(exitT, eta * eta * both[e][1]));
    CHECK(evExit == evT);
  }
}
