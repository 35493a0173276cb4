#include "slideline/solver/output_recorder.hpp"

#include <algorithm>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/solver/step_control.hpp"

namespace slideline {

namespace {

/// `name`, or when `used` holds it already name_2, name_3, ...; the result is added to `used`.
/// A deck may give two interfaces or supports one name (two *BOUNDARY_PRESCRIBED_MOTION cards
/// without _ID on one node set are both "motion_<nsid>"), and every channel path must be unique.
std::string unique_name(std::vector<std::string>& used, const std::string& name) {
  std::string n = name;
  for (int k = 2; std::find(used.begin(), used.end(), n) != used.end(); ++k) n = name + "_" + std::to_string(k);
  used.push_back(n);
  return n;
}

}  // namespace

void OutputRecorder::build_channels(const OutputSources& src) {
  channels_.clear();
  contact_outputs_.clear();
  std::vector<std::string> names, used;
  for (const auto& c : src.contacts) {
    const std::string title = unique_name(used, c->name());
    channels_.push_back({"interfaces/" + title + "/slave_force", 3});
    channels_.push_back({"interfaces/" + title + "/master_force", 3});
    names.clear();
    c->append_output_names(names);
    for (auto& s : names) channels_.push_back({"interfaces/" + title + "/" + s, 3});
    contact_outputs_.push_back(3 * names.size());
  }
  used.clear();
  for (const auto& g : src.supports) channels_.push_back({"supports/" + unique_name(used, g.name) + "/reaction", 3});
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
  // Erosion's energy only where a part can erode: other histories keep their channels.
  erodes_ = std::any_of(src.blocks.begin(), src.blocks.end(), [](const auto& b) { return b->erosion() != nullptr; });
  if (erodes_) channels_.push_back({"energy/eroded", 1});
  // Per-part energies where a part can erode (the eroded energies leave the model's internal
  // energy; the parts' show where): the part energy monitor's, in its part order.
  energy_parts_ = erodes_ && src.part_energy != nullptr;
  if (energy_parts_) {
    // The monitor is reset after the channels are built: its parts are the blocks' in order of
    // first block, as here.
    std::vector<Id> parts;
    for (const auto& b : src.blocks)
      if (std::find(parts.begin(), parts.end(), b->part_id()) == parts.end()) parts.push_back(b->part_id());
    for (Id part : parts)
      for (const char* e : {"internal_energy", "hourglass_energy", "eroded_internal", "eroded_hourglass"})
        channels_.push_back({"parts/" + std::to_string(part) + "/" + e, 1});
  }
  plastic_parts_.clear();
  for (std::size_t b = 0; b < src.blocks.size(); ++b) {
    if (!src.blocks[b]->has_plasticity()) continue;
    const Id part = src.blocks[b]->part_id();
    auto it = std::find_if(plastic_parts_.begin(), plastic_parts_.end(), [&](const PartBlocks& p) { return p.part == part; });
    if (it == plastic_parts_.end()) it = plastic_parts_.insert(plastic_parts_.end(), PartBlocks{part, {}});
    it->blocks.push_back(b);
  }
  for (const PartBlocks& p : plastic_parts_) {
    channels_.push_back({"parts/" + std::to_string(p.part) + "/max_plastic_strain", 1});
    channels_.push_back({"parts/" + std::to_string(p.part) + "/plastic_work", 1});
  }
  // Mass scaling every cycle: the energy it put in and each part's added mass, only then.
  mass_parts_.clear();
  if (!src.added_mass.empty()) {
    channels_.push_back({"energy/mass_scaling", 1});
    for (std::size_t b = 0; b < src.added_mass.size(); ++b) {
      const Id part = src.added_mass[b].part;
      auto it = std::find_if(mass_parts_.begin(), mass_parts_.end(), [&](const PartBlocks& p) { return p.part == part; });
      if (it == mass_parts_.end()) it = mass_parts_.insert(mass_parts_.end(), PartBlocks{part, {}});
      it->blocks.push_back(b);
    }
    for (const PartBlocks& p : mass_parts_) channels_.push_back({"parts/" + std::to_string(p.part) + "/added_mass", 1});
  }
  std::size_t width = 0;
  for (const auto& c : channels_) width += c.components;
  history_values_.assign(width, 0.0);
  state_values_.assign(3 * static_cast<std::size_t>(n), 0.0);
  last_history_ = -1.0;
  last_state_ = -1.0;
}

std::vector<std::vector<CellSlot>> output_cell_slots(const ElementBlocks& blocks,
                                                     std::span<const TopologyCells> cells) {
  std::vector<Index> next(cells.size(), 0);
  std::vector<std::vector<CellSlot>> slots(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    slots[b].resize(static_cast<std::size_t>(blocks[b]->element_count()));
    blocks[b]->topology().for_each_element([&](const TopologyRun& run, Index e, std::size_t) {
      std::size_t t = 0;
      while (t < cells.size() && cells[t].topology != run.topology) ++t;
      if (t == cells.size()) throw Error("output: a block's topology has no cell group");
      slots[b][static_cast<std::size_t>(e)] = {t, next[t]++};
    });
  }
  return slots;
}

std::vector<TopologyCellInfo> output_cell_info(const ElementBlocks& blocks, std::span<const TopologyCells> cells) {
  std::vector<TopologyCellInfo> info(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) {
    info[t].part_ids.assign(cells[t].count(), 0);
    info[t].material_ids.assign(cells[t].count(), 0);
    info[t].thickness.assign(cells[t].count(), 0.0);
  }
  const auto slots = output_cell_slots(blocks, cells);
  for (std::size_t b = 0; b < blocks.size(); ++b)
    blocks[b]->topology().for_each_element([&](const TopologyRun& run, Index e, std::size_t) {
      const CellSlot s = slots[b][static_cast<std::size_t>(e)];
      const auto c = static_cast<std::size_t>(s.cell);
      info[s.topology].part_ids[c] = blocks[b]->part_id();
      info[s.topology].material_ids[c] = blocks[b]->material_id();
      info[s.topology].thickness[c] = run.thickness;
    });
  return info;
}

void OutputRecorder::begin(const std::vector<OutputSink*>& sinks, const MeshDescription& mesh,
                           const ElementBlocks& blocks) {
  const std::size_t n3 = mesh.x0.size();
  velocity_.assign(n3, 0.0);
  acceleration_.assign(n3, 0.0);
  contact_force_.assign(n3, 0.0);
  slots_ = output_cell_slots(blocks, mesh.cells);
  block_cells_.resize(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b)
    block_cells_[b].assign(static_cast<std::size_t>(blocks[b]->element_count()), CellOutput{});
  cell_fields_.assign(mesh.cells.size(), TopologyCellFields{});
  const bool erodes = std::any_of(blocks.begin(), blocks.end(), [](const auto& b) { return b->erosion() != nullptr; });
  for (std::size_t t = 0; t < mesh.cells.size(); ++t) {
    const std::size_t n = mesh.cells[t].count();
    TopologyCellFields& f = cell_fields_[t];
    f.stress.assign(6 * n, 0.0);
    if (mesh.cells[t].topology->dimension == 2) {
      f.stress_bottom.assign(6 * n, 0.0);
      f.stress_top.assign(6 * n, 0.0);
    }
    f.von_mises.assign(n, 0.0);
    f.plastic_strain.assign(n, 0.0);
    f.energy_density.assign(n, 0.0);
    if (erodes) f.deleted.assign(n, 0.0);
  }
  // The current shell thickness, where a part changes it: every shell cell of the topology starts
  // at its section's (collect_state overwrites the changing parts').
  if (std::any_of(blocks.begin(), blocks.end(), [](const auto& b) { return !b->current_thickness().empty(); })) {
    const std::vector<TopologyCellInfo> info = output_cell_info(blocks, mesh.cells);
    for (std::size_t t = 0; t < mesh.cells.size(); ++t)
      if (mesh.cells[t].topology->dimension == 2) cell_fields_[t].current_thickness = info[t].thickness;
  }
  for (auto* s : sinks) s->begin(channels_, mesh);
  sinks_ = &sinks;
}

void OutputRecorder::collect_state(const OutputSources& src) {
  const NodalFields& nodes = src.nodes;
  const auto put = [](std::vector<Real>& out, const Vec3Field& f, std::size_t i) {
    out[3 * i] = f.x[i];
    out[3 * i + 1] = f.y[i];
    out[3 * i + 2] = f.z[i];
  };
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    state_values_[3 * i] = nodes.x.x[i] - nodes.x0.x[i];
    state_values_[3 * i + 1] = nodes.x.y[i] - nodes.x0.y[i];
    state_values_[3 * i + 2] = nodes.x.z[i] - nodes.x0.z[i];
    put(velocity_, nodes.v, i);
    put(acceleration_, nodes.a, i);
    if (!nodes.f_contact.x.empty()) put(contact_force_, nodes.f_contact, i);
  }
  for (std::size_t b = 0; b < src.blocks.size(); ++b) {
    src.blocks[b]->cell_outputs(nodes, block_cells_[b]);
    const std::span<const Real> thickness = src.blocks[b]->current_thickness();
    for (std::size_t e = 0; e < block_cells_[b].size(); ++e) {
      const CellOutput& c = block_cells_[b][e];
      const CellSlot s = slots_[b][e];
      TopologyCellFields& f = cell_fields_[s.topology];
      const auto k = static_cast<std::size_t>(s.cell);
      std::copy(c.stress.begin(), c.stress.end(), f.stress.begin() + static_cast<std::ptrdiff_t>(6 * k));
      if (!f.stress_top.empty()) {
        std::copy(c.stress_bottom.begin(), c.stress_bottom.end(), f.stress_bottom.begin() + static_cast<std::ptrdiff_t>(6 * k));
        std::copy(c.stress_top.begin(), c.stress_top.end(), f.stress_top.begin() + static_cast<std::ptrdiff_t>(6 * k));
      }
      f.von_mises[k] = von_mises(c.stress);
      f.plastic_strain[k] = c.plastic_strain;
      f.energy_density[k] = c.energy_density;
      if (!f.deleted.empty()) f.deleted[k] = c.deleted ? 1.0 : 0.0;
      if (!thickness.empty() && !f.current_thickness.empty()) f.current_thickness[k] = thickness[e];
    }
  }
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
  if (erodes_) values[k++] = src.energy.eroded();
  if (energy_parts_) {
    const PartEnergyMonitor& m = *src.part_energy;
    for (std::size_t p = 0; p < m.part_count(); ++p) {
      values[k++] = m.internal_energy(p);
      values[k++] = m.hourglass_energy(p);
      values[k++] = m.eroded_internal_energy(p);
      values[k++] = m.eroded_hourglass_energy(p);
    }
  }
  for (const PartBlocks& p : plastic_parts_) {
    PlasticityTotals t;
    for (std::size_t b : p.blocks) t += src.blocks[b]->plasticity_totals(src.nodes);
    values[k++] = t.max_plastic_strain;
    values[k++] = t.plastic_work;
  }
  if (!src.added_mass.empty()) {
    values[k++] = src.energy.mass_scaling;
    for (const PartBlocks& p : mass_parts_) {
      Real added = 0.0;
      for (std::size_t b : p.blocks) added += src.added_mass[b].added;
      values[k++] = added;
    }
  }
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
    collect_state(src);
    const StateFields state{state_values_, velocity_, acceleration_, contact_force_, cell_fields_};
    for (auto* s : sinks) s->write_state(t, state);
    last_state_ = t;
  }
}

}  // namespace slideline
