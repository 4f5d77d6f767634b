// Modules run in their declared stage order whatever order they were added in, and get the
// restored() hook after a checkpoint is read.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {
class Recorder final : public Module {
 public:
  Recorder(std::string name, ModuleStage stage, std::vector<std::string>& log)
      : name_(std::move(name)), stage_(stage), log_(log) {}
  std::string name() const override { return name_; }
  ModuleStage stage() const override { return stage_; }
  void pre_force(Simulation&) override { log_.push_back(name_ + ".pre"); }
  void end_of_step(Simulation&) override { log_.push_back(name_ + ".end"); }
  void restored(Simulation&) override { log_.push_back(name_ + ".restored"); }

 private:
  std::string name_;
  ModuleStage stage_;
  std::vector<std::string>& log_;
};

std::unique_ptr<Simulation> with_modules(std::vector<std::string>& log) {
  auto sim = make_simulation({});
  add_sphere(*sim, {0, 0, 0}, 0.001);
  sim->dt = 1e-6;
  sim->modules.push_back(std::make_unique<Recorder>("out", ModuleStage::output, log));
  sim->modules.push_back(std::make_unique<Recorder>("measure", ModuleStage::observation, log));
  sim->modules.push_back(std::make_unique<Recorder>("break", ModuleStage::physics, log));
  sim->modules.push_back(std::make_unique<Recorder>("pour", ModuleStage::insertion, log));
  return sim;
}
}  // namespace

TEST(ModuleOrder, StagesRunInDeclaredOrder) {
  std::vector<std::string> log;
  auto sim = with_modules(log);
  sim->step();
  EXPECT_EQ(log, (std::vector<std::string>{"pour.pre", "break.pre", "measure.pre", "out.pre",
                                           "pour.end", "break.end", "measure.end", "out.end"}));
}

TEST(ModuleOrder, RestoredFollowsACheckpoint) {
  std::vector<std::string> log;
  auto sim = with_modules(log);
  sim->step();
  Archive a;
  sim->save(a);
  std::vector<std::string> log2;
  auto again = with_modules(log2);
  again->load(a);
  EXPECT_EQ(log2, (std::vector<std::string>{"pour.restored", "break.restored", "measure.restored",
                                            "out.restored"}));
}
