#pragma once
/// The total load on a node: the one place where f_int + f_ext + f_contact (and the moments
/// m_int + m_ext + m_contact) is formed. The order of the additions is part of the results' bits
/// (the 19 sslide histories are checked bitwise), so every phase that needs the total calls this.
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Component c of node i of internal + external (+ contact, with kContact) load, from the three
/// fields of one kind (forces: f_int, f_ext, f_contact; moments: m_int, m_ext, m_contact). Without
/// contact the contact field is not read (it stays zero and the sum skips it).
template <bool kContact>
inline Real total_load(const Vec3Field& internal, const Vec3Field& external, const Vec3Field& contact, int c,
                       Index i) {
  if constexpr (kContact) return internal[c][i] + external[c][i] + contact[c][i];
  else return internal[c][i] + external[c][i];
}

/// Component c of the total force on node i (f_int + f_ext + f_contact).
template <bool kContact = true>
inline Real total_force(const NodalFields& n, int c, Index i) {
  return total_load<kContact>(n.f_int, n.f_ext, n.f_contact, c, i);
}

/// Component c of the total moment on node i (m_int + m_ext + m_contact).
template <bool kContact = true>
inline Real total_moment(const NodalFields& n, int c, Index i) {
  return total_load<kContact>(n.m_int, n.m_ext, n.m_contact, c, i);
}

}  // namespace slideline
