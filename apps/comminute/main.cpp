// The `comminute` command line: a thin front end over the library.
#include <fmt/format.h>

#include <cstdio>
#include <map>

#include "command.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"

namespace comminute::app {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> c;
  return c;
}
}  // namespace

bool add_command(Command c) {
  registry().push_back(std::move(c));
  return true;
}
const std::vector<Command>& commands() {
  return registry();
}

}  // namespace comminute::app

int main(int argc, char** argv) {
  using namespace comminute;
  give_back_freed_arrays();
  CLI::App cli{"comminute — DEM and population-balance simulation of particle breakage"};
  cli.set_version_flag("--version", std::string("comminute ") + COMMINUTE_VERSION);
  cli.require_subcommand(1);
  std::map<std::string, std::function<int()>> actions;
  for (const auto& c : app::commands()) {
    CLI::App* sub = cli.add_subcommand(c.name, c.description);
    actions[c.name] = c.setup(*sub);
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  try {
    for (auto* sub : cli.get_subcommands()) return actions.at(sub->get_name())();
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const SimulationError& e) {
    fmt::print(stderr, "simulation stopped: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
