// blockcontact: command-line driver of slideline (docs/cli.md).
#include <fmt/core.h>

#include "commands.hpp"
#include "slideline/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"blockcontact: explicit finite-element contact of two blocks (DYNA3D verification suite)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "blockcontact 0.1.0");
  int exit_code = blockcontact::kOk;
  blockcontact::register_run(app, exit_code);
  blockcontact::register_check(app, exit_code);
  blockcontact::register_generate(app, exit_code);
  blockcontact::register_verify(app, exit_code);
  blockcontact::register_keywords(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const slideline::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return blockcontact::kBadInput;
  } catch (const slideline::NotImplementedError& e) {
    fmt::print(stderr, "not implemented: {}\n", e.what());
    return blockcontact::kNotImplemented;
  } catch (const slideline::InstabilityError& e) {
    fmt::print(stderr, "instability at t = {:g} (cycle {}): {}\n", e.time(), e.cycle(), e.what());
    return blockcontact::kInstability;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return blockcontact::kFailure;
  }
  return exit_code;
}
