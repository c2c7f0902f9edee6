// SPDX-License-Identifier: Apache-2.0
// Issue 39, item 3: the rigid contact law's small dense solves (numerics/redundant_solve.hpp: the
// envelope Cholesky of the Delassus matrix and Gaussian elimination, both dropping redundant rows)
// beside Eigen's decompositions of the same systems in the same run (LLT and LDLT for the
// Cholesky, PartialPivLU for Gauss; fixed maximum sizes, so none allocates). The systems are the
// Delassus matrices W = J M^-1 J^T of a chain of n blocks on the ground (each joint two ends, each
// end a normal and a tangential row, coupling the two blocks it joins): banded, as an arch's or a
// column's. Each benchmark copies the matrix and solves; the copy is in every variant.
#include <benchmark/benchmark.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <stdexcept>
#include <vector>

#include "blockdyn/numerics/redundant_solve.hpp"

namespace {

constexpr int kMax = 80;
using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, kMax, kMax>;
using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;

struct System {
  int m = 0;
  std::vector<double> A, b;  // row-major m x m
};

// The Delassus matrix of `blocks` blocks in a chain (joint j between blocks j - 1 and j; joint 0
// on the ground), each row a random unit-scale direction on the 3 coordinates of its blocks.
System chain(int blocks) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  const int rows = 4 * blocks, coords = 3 * blocks;
  std::vector<double> J(std::size_t(rows * coords), 0.0);
  for (int j = 0; j < blocks; ++j)
    for (int r = 0; r < 4; ++r)
      for (int k = j - 1; k <= j; ++k)
        if (k >= 0)
          for (int c = 0; c < 3; ++c) J[std::size_t((4 * j + r) * coords + 3 * k + c)] = u(rng);
  std::vector<double> inv_mass(static_cast<std::size_t>(coords));
  for (auto& w : inv_mass) w = 0.5 + 0.5 * (u(rng) + 1);
  System s;
  s.m = rows;
  s.A.assign(std::size_t(rows * rows), 0.0);
  s.b.resize(std::size_t(rows));
  for (int i = 0; i < rows; ++i) {
    s.b[std::size_t(i)] = u(rng);
    for (int k = 0; k < rows; ++k) {
      double w = 0;
      for (int c = 0; c < coords; ++c)
        w += J[std::size_t(i * coords + c)] * inv_mass[std::size_t(c)] * J[std::size_t(k * coords + c)];
      s.A[std::size_t(i * rows + k)] = w;
    }
    s.A[std::size_t(i * rows + i)] += 1e-9;  // the contact's compliance
  }
  return s;
}

const System& system_of(int blocks) {
  static std::array<System, 21> cache;
  if (cache[std::size_t(blocks)].m == 0) cache[std::size_t(blocks)] = chain(blocks);
  return cache[std::size_t(blocks)];
}

// The residual |A x - b|_inf of a solution, checked once per benchmark (the variants must agree).
double residual(const System& s, const double* x) {
  double r = 0;
  for (int i = 0; i < s.m; ++i) {
    double v = -s.b[std::size_t(i)];
    for (int k = 0; k < s.m; ++k) v += s.A[std::size_t(i * s.m + k)] * x[k];
    r = std::fmax(r, std::fabs(v));
  }
  return r;
}

void check(benchmark::State& state, const System& s, const double* x) {
  const double r = residual(s, x);
  state.counters["residual"] = r;
  if (!(r < 1e-6)) state.SkipWithError("the solve disagrees with the system");
}

void BM_CholeskyEnvelope(benchmark::State& state) {
  const System& s = system_of(int(state.range(0)));
  std::array<double, kMax * kMax> A{};
  std::array<double, kMax> b{};
  std::array<int, kMax> dropped{};
  for (auto _ : state) {
    std::copy(s.A.begin(), s.A.end(), A.begin());
    std::copy(s.b.begin(), s.b.end(), b.begin());
    blockdyn::cholesky_solve(A.data(), b.data(), s.m, s.m, 1e-14, dropped.data());
    benchmark::DoNotOptimize(b.data());
  }
  check(state, s, b.data());
  state.counters["unknowns"] = s.m;
}

void BM_EigenLLT(benchmark::State& state) {
  const System& s = system_of(int(state.range(0)));
  Mat A(s.m, s.m);
  Vec b(s.m), x(s.m);
  Eigen::LLT<Mat> llt(s.m);
  for (auto _ : state) {
    A = Eigen::Map<const Mat>(s.A.data(), s.m, s.m);
    b = Eigen::Map<const Vec>(s.b.data(), s.m);
    llt.compute(A);
    x = llt.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
  check(state, s, x.data());
  state.counters["unknowns"] = s.m;
}

void BM_EigenLDLT(benchmark::State& state) {
  const System& s = system_of(int(state.range(0)));
  Mat A(s.m, s.m);
  Vec b(s.m), x(s.m);
  Eigen::LDLT<Mat> ldlt(s.m);
  for (auto _ : state) {
    A = Eigen::Map<const Mat>(s.A.data(), s.m, s.m);
    b = Eigen::Map<const Vec>(s.b.data(), s.m);
    ldlt.compute(A);
    x = ldlt.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
  check(state, s, x.data());
  state.counters["unknowns"] = s.m;
}

void BM_GaussPartialPivot(benchmark::State& state) {
  const System& s = system_of(int(state.range(0)));
  std::array<double, kMax * kMax> A{};
  std::array<double, kMax> b{};
  std::array<int, kMax> piv{};
  for (auto _ : state) {
    std::copy(s.A.begin(), s.A.end(), A.begin());
    std::copy(s.b.begin(), s.b.end(), b.begin());
    blockdyn::gauss_solve(A.data(), b.data(), s.m, s.m, 1e-14, piv.data());
    benchmark::DoNotOptimize(b.data());
  }
  check(state, s, b.data());
  state.counters["unknowns"] = s.m;
}

void BM_EigenPartialPivLU(benchmark::State& state) {
  const System& s = system_of(int(state.range(0)));
  Mat A(s.m, s.m);
  Vec b(s.m), x(s.m);
  Eigen::PartialPivLU<Mat> lu(s.m);
  for (auto _ : state) {
    A = Eigen::Map<const Mat>(s.A.data(), s.m, s.m);
    b = Eigen::Map<const Vec>(s.b.data(), s.m);
    lu.compute(A);
    x = lu.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
  check(state, s, x.data());
  state.counters["unknowns"] = s.m;
}

// 2, 5, 10 and 20 blocks: 8, 20, 40 and 80 unknowns.
BENCHMARK(BM_CholeskyEnvelope)->Arg(2)->Arg(5)->Arg(10)->Arg(20);
BENCHMARK(BM_EigenLLT)->Arg(2)->Arg(5)->Arg(10)->Arg(20);
BENCHMARK(BM_EigenLDLT)->Arg(2)->Arg(5)->Arg(10)->Arg(20);
BENCHMARK(BM_GaussPartialPivot)->Arg(2)->Arg(5)->Arg(10)->Arg(20);
BENCHMARK(BM_EigenPartialPivLU)->Arg(2)->Arg(5)->Arg(10)->Arg(20);

}  // namespace
