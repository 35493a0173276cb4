#pragma once
/// A visitor from a set of lambdas: std::visit(Overloaded{[](const A&) {...}, [](const B&) {...}}, v).
/// Written without a generic case, such a visit fails to compile when the variant gains an
/// alternative that no lambda takes.

namespace slideline {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

}  // namespace slideline
