#pragma once
// `comminute couple`: the couple case read and checked before anything runs, for `couple` and for
// `check` (which validates a couple case as `couple` would before its DEM stage).
#include <filesystem>

#include "case_loading.hpp"
#include "comminute/run/couple.hpp"

namespace comminute::app {

struct PreparedCouple {
  run::CoupleCase couple;
  LoadedCase dem;
  run::DemObservers observers;
  bool pbm_checked = false;  // false: the pbm case waits for files the DEM stage writes
};

// Reads [couple], the DEM case (sets the OpenMP thread count of couple.threads) and the pbm case;
// throws InputError on anything wrong.
PreparedCouple prepare_couple_case(const std::filesystem::path& file);

}  // namespace comminute::app
