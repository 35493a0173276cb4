#include "slideline/solver/output_recorder.hpp"

#include <algorithm>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/solver/step_control.hpp"

namespace slideline {

void OutputRecorder::build_channels(const OutputSources& src) {
  channels_.clear();
  contact_outputs_.clear();
  std::vector<std::string> names;
  for (const auto& c : src.contacts) {
    channels_.push_back({"interfaces/" + c->name() + "/slave_force", 3});
    channels_.push_back({"interfaces/" + c->name() + "/master_force", 3});
    names.clear();
    c->append_output_names(names);
    for (auto& s : names) channels_.push_back({"interfaces/" + c->name() + "/" + s, 3});
    contact_outputs_.push_back(3 * names.size());
  }
  for (const auto& g : src.supports) channels_.push_back({"supports/" + g.name + "/reaction", 3});
  constraint_outputs_.clear();
  for (const auto& c : src.constraints) {
    names.clear();
    c->append_output_names(names);
    for (auto& s : names) channels_.push_back({std::move(s), 3});
    constraint_outputs_.push_back(3 * names.size());
  }
  const Index n = static_cast<Index>(src.nodes.size());
  for (Index i : src.history_nodes) {
    if (i < 0 || i >= n) throw InputError("history node index out of range");
    channels_.push_back({"nodes/" + std::to_string(src.nodes.ids[i]) + "/displacement", 3});
  }
  for (const char* e : EnergyReport::names) channels_.push_back({std::string("energy/") + e, 1});
  std::size_t width = 0;
  for (const auto& c : channels_) width += c.components;
  history_values_.assign(width, 0.0);
  state_values_.assign(3 * static_cast<std::size_t>(n), 0.0);
  last_history_ = -1.0;
  last_state_ = -1.0;
}

void OutputRecorder::begin(const std::vector<OutputSink*>& sinks, const MeshDescription& mesh) {
  for (auto* s : sinks) s->begin(channels_, mesh);
  sinks_ = &sinks;
}

void OutputRecorder::end() {
  if (sinks_ == nullptr) return;
  for (auto* s : *sinks_) s->flush();
  sinks_ = nullptr;
}

void OutputRecorder::collect_history(const OutputSources& src) {
  auto& values = history_values_;
  std::size_t k = 0;
  auto put3 = [&](const Vec3& v) {
    values[k++] = v[0];
    values[k++] = v[1];
    values[k++] = v[2];
  };
  const ContactManager& contacts = src.contacts;
  for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
    // An interface before its birth or after its death carries no force.
    const bool on = contacts.active(ci);
    put3(on ? contacts[ci].slave_force() : Vec3::Zero());
    put3(on ? contacts[ci].master_force() : Vec3::Zero());
    const auto extra = std::span<Real>(values).subspan(k, contact_outputs_[ci]);
    if (on) contacts[ci].write_output_values(extra);
    else std::fill(extra.begin(), extra.end(), 0.0);
    k += contact_outputs_[ci];
  }
  for (const auto& g : src.supports) put3(g.reaction);
  for (std::size_t c = 0; c < src.constraints.size(); ++c) {
    src.constraints[c]->write_output_values(std::span<Real>(values).subspan(k, constraint_outputs_[c]));
    k += constraint_outputs_[c];
  }
  for (Index i : src.history_nodes) put3(src.nodes.displacement(i));
  for (Real v : src.energy.values()) values[k++] = v;
}

void OutputRecorder::record(const OutputSources& src, Real t, Real history_interval, Real state_interval, Real tol,
                            bool force) {
  if (sinks_ == nullptr) return;
  const auto& sinks = *sinks_;
  const Real hi = history_interval;
  const bool history_due =
      force || hi <= 0.0 || last_history_ < 0.0 || t >= next_output_time(hi, last_history_) - tol;
  if (history_due && t != last_history_) {
    collect_history(src);
    for (auto* s : sinks) s->write_history(t, history_values_);
    last_history_ = t;
  }
  const Real si = state_interval;
  if (si > 0.0 && (force || last_state_ < 0.0 || t >= next_output_time(si, last_state_) - tol) &&
      t != last_state_) {
    const NodalFields& nodes = src.nodes;
    const std::size_t n = nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      state_values_[3 * i] = nodes.x.x[i] - nodes.x0.x[i];
      state_values_[3 * i + 1] = nodes.x.y[i] - nodes.x0.y[i];
      state_values_[3 * i + 2] = nodes.x.z[i] - nodes.x0.z[i];
    }
    for (auto* s : sinks) s->write_state(t, state_values_);
    last_state_ = t;
  }
}

}  // namespace slideline
