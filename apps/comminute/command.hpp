#pragma once
// Sub-commands of the `comminute` program. Each lives in its own cmd_*.cpp and registers itself:
//   static const bool reg = add_command({"pbm", "Solve a population balance", &setup_pbm});
// setup() declares the sub-command's options on `app` and returns the action that runs it
// (exit code). Errors thrown from actions are reported by main().
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace comminute::app {

struct Command {
  std::string name;
  std::string description;
  std::function<std::function<int()>(CLI::App& sub)> setup;
};

bool add_command(Command c);
const std::vector<Command>& commands();

}  // namespace comminute::app
