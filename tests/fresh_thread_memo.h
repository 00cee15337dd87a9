// The per-thread memo checks of the fixed rules (diffuse, sheen): the same cases run on a fresh
// thread (a cold memo) over views in order and reversed must give the same bits.
#pragma once
#include <catch2/catch.hpp>

#include <cstddef>
#include <thread>
#include <vector>

namespace kiln::test {

/// The results `cases(mu, out)` appends for each of `mus`, visited in order or reversed, all on
/// one fresh thread (its per-thread memos start empty).
template <class Got, class Cases>
std::vector<Got> CasesOnFreshThread(const std::vector<double>& mus, bool reversed, Cases cases) {
  std::vector<Got> out;
  std::thread worker([&] {
    for (size_t k = 0; k < mus.size(); ++k) cases(mus[reversed ? mus.size() - 1 - k : k], out);
  });
  worker.join();
  return out;
}

/// Runs `cases` (CasesOnFreshThread: `per` results a view) forward and reversed and holds each
/// view's results alike: `same(a, b)` CHECKs one forward result against its reversed twin.
/// Returns the forward results.
template <class Got, class Cases, class Same>
std::vector<Got> RequireSameInEitherOrder(const std::vector<double>& mus, size_t per, Cases cases,
                                          Same same) {
  const std::vector<Got> forward = CasesOnFreshThread<Got>(mus, false, cases);
  const std::vector<Got> backward = CasesOnFreshThread<Got>(mus, true, cases);
  REQUIRE(forward.size() == mus.size() * per);
  REQUIRE(backward.size() == forward.size());
  for (size_t k = 0; k < mus.size(); ++k)
    for (size_t i = 0; i < per; ++i) {
      INFO("mu " << mus[k] << " case " << i);
      same(forward[k * per + i], backward[(mus.size() - 1 - k) * per + i]);
    }
  return forward;
}

}  // namespace kiln::test
