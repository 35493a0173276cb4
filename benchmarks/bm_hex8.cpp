// Per-element costs of the hexahedron kernel's parts (one element, cache resident), to see where
// the time of the force update goes.
#include <benchmark/benchmark.h>

#include "slideline/element/hex8.hpp"
#include "slideline/material/mooney_rivlin.hpp"

using namespace slideline;

namespace {
hex8::NodeMat element() {
  hex8::NodeMat X;
  X << 0.0, 0.0, 0.0, 1.2, 0.1, -0.05, 1.1, 0.9, 0.1, -0.1, 1.05, 0.0, 0.05, -0.1, 0.95, 1.0, 0.05,
      1.2, 1.3, 1.2, 0.9, 0.1, 0.95, 1.1;
  return X;
}

void BM_VolumeGradient(benchmark::State& state) {
  hex8::NodeMat X = element();
  for (auto _ : state) {
    benchmark::DoNotOptimize(X);
    hex8::NodeMat g = hex8::volume_gradient(X);
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_VolumeGradient);

void BM_MaxFaceArea(benchmark::State& state) {
  hex8::NodeMat X = element();
  for (auto _ : state) {
    benchmark::DoNotOptimize(X);
    benchmark::DoNotOptimize(hex8::max_face_area(X));
  }
}
BENCHMARK(BM_MaxFaceArea);

void BM_HourglassStiffness(benchmark::State& state) {
  hex8::NodeMat X = element();
  const hex8::NodeMat B = hex8::volume_gradient(X) / 1.3;
  hex8::NodeMat U = X * 0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(X);
    benchmark::DoNotOptimize(U);
    const hex8::HgMat gam = hex8::hourglass_shape(X, B);
    hex8::NodeMat fh = -2.0 * (gam.transpose() * (gam * U));
    benchmark::DoNotOptimize(fh);
  }
}
BENCHMARK(BM_HourglassStiffness);

void BM_MooneyRivlinStress(benchmark::State& state) {
  const MooneyRivlin m(0.01, 909.091, 0.0, 0.1);
  Mat3 F = Mat3::Identity();
  F(0, 1) = 0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(F);
    Mat3 s = m.cauchy_stress(F);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_MooneyRivlinStress);

void BM_DeformationGradient(benchmark::State& state) {
  hex8::NodeMat X = element();
  const hex8::NodeMat B = hex8::volume_gradient(X) / 1.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(X);
    const Mat3 finv = X.transpose() * B;
    Mat3 F = finv.inverse();
    benchmark::DoNotOptimize(F);
  }
}
BENCHMARK(BM_DeformationGradient);

void BM_StressDivergence(benchmark::State& state) {
  hex8::NodeMat X = element();
  const hex8::NodeMat B = hex8::volume_gradient(X) / 1.3;
  Mat3 s = Mat3::Identity();
  for (auto _ : state) {
    benchmark::DoNotOptimize(s);
    hex8::NodeMat f = -1.3 * (B * s);
    benchmark::DoNotOptimize(f);
  }
}
BENCHMARK(BM_StressDivergence);
}  // namespace

// The same parts for a batch of kLanes elements, one per lane (what HexBlock runs); divide the
// time by kLanes for the cost per element (the counter per_element does).
namespace {
struct Batch {
  hex8::NodeLanes x, y, z;
};

Batch batch() {
  const hex8::NodeMat X = element();
  Batch b;
  for (int k = 0; k < 8; ++k)
    for (int l = 0; l < kLanes; ++l) {
      const Real s = 1.0 + 0.01 * l;
      b.x[k][l] = s * X(k, 0);
      b.y[k][l] = X(k, 1);
      b.z[k][l] = X(k, 2) / s;
    }
  return b;
}

void per_element(benchmark::State& state) {
  state.counters["per_element"] = benchmark::Counter(
      kLanes, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_VolumeGradientLanes(benchmark::State& state) {
  Batch b = batch();
  hex8::NodeLanes gx, gy, gz;
  for (auto _ : state) {
    benchmark::DoNotOptimize(b);
    hex8::volume_gradient(b.x, b.y, b.z, gx, gy, gz);
    benchmark::DoNotOptimize(gx);
    benchmark::DoNotOptimize(gy);
    benchmark::DoNotOptimize(gz);
  }
  per_element(state);
}
BENCHMARK(BM_VolumeGradientLanes);

void BM_MaxFaceAreaLanes(benchmark::State& state) {
  Batch b = batch();
  for (auto _ : state) {
    benchmark::DoNotOptimize(b);
    Lanes a = hex8::max_face_area(b.x, b.y, b.z);
    benchmark::DoNotOptimize(a);
  }
  per_element(state);
}
BENCHMARK(BM_MaxFaceAreaLanes);

void BM_HourglassLanes(benchmark::State& state) {
  Batch b = batch();
  hex8::NodeLanes gx, gy, gz, hx, hy, hz;
  hex8::volume_gradient(b.x, b.y, b.z, gx, gy, gz);
  for (auto _ : state) {
    benchmark::DoNotOptimize(b);
    hex8::hourglass_resistance(b.x, b.y, b.z, gx, gy, gz, b.z, b.x, b.y, hx, hy, hz);
    benchmark::DoNotOptimize(hx);
    benchmark::DoNotOptimize(hy);
    benchmark::DoNotOptimize(hz);
  }
  per_element(state);
}
BENCHMARK(BM_HourglassLanes);

void BM_DeformationGradientAndStressLanes(benchmark::State& state) {
  const MooneyRivlin m(0.01, 909.091, 0.0, 0.1);
  Tensor3<Lanes> finv;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) finv[i][j] = Lanes::Constant(i == j ? 1.0 : 0.01 * (i - j));
  for (auto _ : state) {
    benchmark::DoNotOptimize(finv);
    Tensor3<Lanes> s = m.cauchy_stress(inverse(finv));
    benchmark::DoNotOptimize(s);
  }
  per_element(state);
}
BENCHMARK(BM_DeformationGradientAndStressLanes);
}  // namespace
