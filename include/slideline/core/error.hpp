#pragma once
/// Error types. Every error says where it comes from: a deck file and line, an element, a node.
#include <stdexcept>
#include <string>

namespace slideline {

/// Base of every exception slideline throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input: a deck, a model or an option that cannot be used as given.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A run that cannot go on: negative volume, non-finite state, time step collapse.
class InstabilityError : public Error {
 public:
  InstabilityError(const std::string& what, double time, long cycle)
      : Error(what), time_(time), cycle_(cycle) {}
  double time() const { return time_; }
  long cycle() const { return cycle_; }

 private:
  double time_;
  long cycle_;
};

/// A feature the model asks for that this version does not run yet.
class NotImplementedError : public Error {
 public:
  using Error::Error;
};

}  // namespace slideline
