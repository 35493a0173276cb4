// ElementErosion (element/element_erosion.hpp): the bookkeeping of deletions and of the energy the
// deleted elements held, on its own (the element blocks and the closed forms are in
// tests/verification/test_erosion.cpp).
#include <gtest/gtest.h>

#include <limits>

#include "slideline/core/parallel.hpp"
#include "slideline/element/element_erosion.hpp"

using namespace slideline;

// An element holds the work of its forces step by step; when its plastic strain reaches the
// failure strain it is deleted, stamped with the time, and what it held is reduced once (per
// chunk, in chunk order), then cleared for the next evaluation.
TEST(ElementErosion, DeletesAtTheFailureStrainAndBooksWhatTheElementHeld) {
  ElementErosion er;
  EXPECT_FALSE(er.active());
  const Index n = kChunkSize + 3;  // two chunks
  er.enable(0.1, n, n + 5);
  ASSERT_TRUE(er.active());
  EXPECT_EQ(er.failure_strain(), 0.1);
  er.set_time(1.0);
  EXPECT_FALSE(er.update(0, 0, 0.05, 2.0, 0.5, 0.25));         // holds 0.5 + 0.125
  EXPECT_FALSE(er.update(n - 1, 1, 0.0999, 4.0, 0.0, 0.25));   // holds 1.0
  EXPECT_FALSE(er.update(1, 0, 0.0, 8.0, 0.0, 0.25));          // holds 2.0, never fails
  Real internal = 0.0, hourglass = 0.0;
  EXPECT_EQ(er.reduce(internal, hourglass), 0);
  EXPECT_EQ(internal, 0.0);
  er.set_time(2.0);
  EXPECT_TRUE(er.update(0, 0, 0.1, 100.0, 100.0, 0.25));  // reaches 0.1: deleted, this step not added
  EXPECT_TRUE(er.update(n - 1, 1, 0.2, 100.0, 0.0, 0.25));
  EXPECT_FALSE(er.update(1, 0, 0.0, 8.0, 0.0, 0.25));
  EXPECT_EQ(er.reduce(internal, hourglass), 2);
  EXPECT_EQ(internal, 0.5 + 1.0);
  EXPECT_EQ(hourglass, 0.125);
  EXPECT_TRUE(er.deleted(0));
  EXPECT_TRUE(er.update(0, 0, 0.0, 1.0, 1.0, 1.0));  // stays deleted, adds nothing
  internal = hourglass = 0.0;
  EXPECT_EQ(er.reduce(internal, hourglass), 0);  // booked once
  EXPECT_EQ(internal, 0.0);
  ASSERT_EQ(er.deletion_times().size(), static_cast<std::size_t>(n));
  EXPECT_EQ(er.deletion_times()[0], 2.0);
  EXPECT_EQ(er.deletion_times()[1], -1.0);
  EXPECT_EQ(er.deletion_times()[static_cast<std::size_t>(n - 1)], 2.0);
  EXPECT_EQ(er.deleted_count(), 2);
}

// eroding_element: without erosion the element's own result; a deleted element has its forces
// zeroed and votes no step.
TEST(ElementErosion, ErodingElementZeroesDeletedElements) {
  struct R {
    Real dt, visc, damp, power;
    bool failed;
    Real power_prev;  ///< of the forces the corner slots held before, at this step's rates
  };
  ElementErosion er;
  int zeroed = 0;
  const auto forces = [](Index) { return R{0.5, 1.0, 2.0, 10.0, false, 4.0}; };
  const auto zero = [&](Index) { ++zeroed; };
  EXPECT_EQ(eroding_element<R>(er, 0, 0.1, forces, [](Index) { return 1.0; }, zero).dt, 0.5);
  er.enable(0.3, 2, 2);
  EXPECT_EQ(eroding_element<R>(er, 0, 0.1, forces, [](Index) { return 0.2; }, zero).power, 10.0);
  const R gone = eroding_element<R>(er, 0, 0.1, forces, [](Index) { return 0.3; }, zero);
  EXPECT_EQ(gone.dt, std::numeric_limits<Real>::max());
  EXPECT_EQ(gone.power, 0.0);
  EXPECT_EQ(zeroed, 1);
  Real internal = 0.0, hourglass = 0.0;
  EXPECT_EQ(er.reduce(internal, hourglass), 1);
  // The kept step's trapezoid, (4 + 10) / 2 net of viscosity and damping, then the deleting
  // step's first half, 4 / 2 (its forces are zero from then on).
  EXPECT_DOUBLE_EQ(internal, ((4.0 + 10.0) / 2.0 - 1.0 - 2.0) * 0.1 + 4.0 / 2.0 * 0.1);
  EXPECT_EQ(eroding_element<R>(er, 0, 0.1, forces, [](Index) { return 0.0; }, zero).power, 0.0);
  EXPECT_EQ(zeroed, 2);
}
