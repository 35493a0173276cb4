#pragma once
// Shared geometry for the hexahedron tests.
#include "slideline/element/hex8.hpp"

namespace test_support {

inline slideline::hex8::NodeMat unit_hex() {
  slideline::hex8::NodeMat X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  return X;
}

/// A clearly non-parallelepiped hexahedron (warped faces, uneven edges), positive volume.
inline slideline::hex8::NodeMat distorted_hex() {
  slideline::hex8::NodeMat X;
  X << 0.0, 0.0, 0.0,   //
      1.2, 0.1, -0.05,  //
      1.1, 0.9, 0.1,    //
      -0.1, 1.05, 0.0,  //
      0.05, -0.1, 0.95, //
      1.0, 0.05, 1.2,   //
      1.3, 1.2, 0.9,    //
      0.1, 0.95, 1.1;
  return X;
}

}  // namespace test_support
