#pragma once
/// The verification criteria of the 19 sslide problems (issue 11, docs/verification.md): the
/// closed-form expected forces, the histories a criterion reads, and the evaluation of every
/// criterion per pairing into table rows.
///
/// Conventions (spec README, "Sign conventions"): F = force on the upper (slave) body,
/// R = force the lower body exerts on its supports (sum of the bottom and right support groups),
/// relative displacement = u_slave - u_master surface point (negative y = interpenetration).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "slideline/scenarios/dyna3d_reported.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/output_sink.hpp"

namespace slideline::scenarios {

/// The closed-form quasi-static answer of one pairing at time t (report section 5).
struct SslideExpected {
  Vec3 force = Vec3::Zero();     ///< F on the upper body
  Vec3 reaction = Vec3::Zero();  ///< R = -F
};
SslideExpected sslide_expected(const SslideProblem& problem, const SslidePairing& pairing, Real t);

/// Channel paths of a pairing (docs/output.md). Type 12 reads the force transmitted between the
/// two bodies (`interfaces/<title>/transmitted_force`) in place of the slave force.
std::string sslide_force_channel(const SslideProblem& problem, const SslidePairing& pairing);
std::string sslide_master_channel(const SslidePairing& pairing);
std::string sslide_support_channel(const std::string& support_title);
std::string sslide_node_channel(Id node);
/// Every channel the criteria of a problem read.
std::vector<std::string> sslide_channels(const SslideProblem& problem);

/// The 3-component time series the criteria read, by channel path.
struct SslideHistories {
  std::vector<Real> time;
  std::map<std::string, std::vector<Vec3>> channels;

  bool has(const std::string& path) const { return channels.count(path) != 0; }
};

/// From an in-memory recording; channels the run did not record are left out.
SslideHistories sslide_histories(const History& history, const SslideProblem& problem);
/// From a run's HDF5 file (docs/output.md); channels absent from the file are left out.
/// Throws Error when the file or its /time cannot be read.
SslideHistories sslide_histories_from_hdf5(const std::string& path, const SslideProblem& problem);

/// One row of the verification table.
struct SslideCriterion {
  std::string problem;
  std::string pairing;
  std::string criterion;        ///< e.g. "mean F_y [0.2,0.3]"
  Real measured = 0.0;          ///< NaN when it could not be measured (see note)
  std::string bound;            ///< the acceptance bound as text, e.g. "10 +- 1%"
  std::optional<Real> dyna3d;   ///< DYNA3D's figure for the same quantity, when reported
  bool pass = false;
  std::string note;             ///< why a row failed to measure, or where a bound comes from
};

/// Evaluates every criterion of every pairing. A channel that is missing, a window with no record
/// and a NaN record fail the rows that need them (measured = NaN, the note says why); nothing is
/// skipped silently.
std::vector<SslideCriterion> evaluate_sslide_criteria(const SslideProblem& problem,
                                                      const SslideHistories& histories,
                                                      const Dyna3dReported& reported);

/// Slope dy/dx (current coordinates, output record r) of the master segments of the monitor's row
/// that the upper body covers by more than half at t = 0: the smallest and largest. Frictionless
/// contact transmits force along the master normal, so -F_x / F_y lies in this range (sslide1k's
/// tilt criterion). nullopt when a node channel of the row is missing or no segment qualifies.
std::optional<std::pair<Real, Real>> sslide_master_slope_range(const SslidePairing& pairing,
                                                                const SslideHistories& histories, std::size_t r);

/// Whether the monitored slave node lies over the master row at record r (its current x within
/// the row's current x extent); nullopt when a node channel is missing.
std::optional<bool> sslide_monitor_over_master(const SslidePairing& pairing, const SslideHistories& histories,
                                               std::size_t r);

/// When the upper body's leading edge (monitor.leading_node, its current x) first passes the
/// +x end of the lower block's top face (the current x of the monitor's row): from then on the
/// block is no longer seated on the interface the criteria judge (issue 17, sslide9ps).
/// `recorded` is false when a channel it needs is missing, short or NaN; `time` is empty when the
/// edge is never passed.
struct SslideEdgeCrossing {
  bool recorded = false;
  std::optional<Real> time;
};
SslideEdgeCrossing sslide_edge_crossing(const SslidePairing& pairing, const SslideHistories& histories);

/// Channel of the Type 9 interface's normal traction at its first segment failure:
/// (max, mean, max/mean) over the slave segments, zero until a segment fails (docs/output.md).
std::string sslide_first_failure_channel(const SslidePairing& pairing);

/// The relative displacement series of a pairing's monitor; empty when a node channel is missing.
std::vector<Vec3> sslide_relative_displacement(const SslidePairing& pairing, const SslideHistories& histories);

}  // namespace slideline::scenarios
