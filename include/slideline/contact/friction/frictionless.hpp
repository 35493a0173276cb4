#pragma once
/// The frictionless policy of the penalty interfaces (compile-time: a frictionless interface
/// compiles without the tangential code). Its counterpart is ExponentialCoulomb
/// (exponential_coulomb.hpp); an interface class takes one of them as its Friction parameter.
namespace slideline {

struct Frictionless {
  /// False: no tangential force, no friction history, no dissipation.
  static constexpr bool enabled = false;
};

}  // namespace slideline
