#include "comminute/breakage/event_log.hpp"

namespace comminute::breakage {

void EventLog::save(Archive& a) const {
  a.put("breakage/log", records_);
  a.put("breakage/fragments", fragments_);
  a.put("breakage/counters", std::vector<std::uint64_t>{breakages_, events_});
}

void EventLog::load(const Archive& a) {
  records_ = a.get<EventRecord>("breakage/log");
  fragments_ = a.get<FragmentRecord>("breakage/fragments");
  const auto c = a.get<std::uint64_t>("breakage/counters");
  if (c.size() != 2) throw Error("checkpoint entry 'breakage/counters' has a wrong size");
  breakages_ = c.at(0);
  events_ = c.at(1);
}

}  // namespace comminute::breakage
