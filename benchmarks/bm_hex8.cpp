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

namespace {
void BM_VolumeGradientCol8(benchmark::State& state) {
  const hex8::NodeMat X = element();
  hex8::Col8 x = X.col(0).array(), y = X.col(1).array(), z = X.col(2).array();
  hex8::Col8 gx, gy, gz;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    hex8::volume_gradient(x, y, z, gx, gy, gz);
    benchmark::DoNotOptimize(gx);
    benchmark::DoNotOptimize(gy);
    benchmark::DoNotOptimize(gz);
  }
}
BENCHMARK(BM_VolumeGradientCol8);

void BM_MaxFaceAreaCol8(benchmark::State& state) {
  const hex8::NodeMat X = element();
  hex8::Col8 x = X.col(0).array(), y = X.col(1).array(), z = X.col(2).array();
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(hex8::max_face_area(x, y, z));
  }
}
BENCHMARK(BM_MaxFaceAreaCol8);
}  // namespace
