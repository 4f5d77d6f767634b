#include "comminute/pbm/collision_spectrum.hpp"

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"

namespace comminute::pbm {

CollisionSpectrum read_collision_spectrum(const CaseTable& t, const std::string& key) {
  const auto path = t.input_file(key);
  const auto csv = CsvColumns::read(path, t.key_path(key));
  CollisionSpectrum s{csv.column("energy_J"), csv.column("frequency_per_s")};
  for (std::size_t r = 0; r < s.energy.size(); ++r)
    if (!(s.energy[r] > 0) || s.frequency[r] < 0)
      throw InputError(path.string(), t.key_path(key), csv.line_of_row(r),
                       "energy_J must be positive and frequency_per_s not negative");
  return s;
}

}  // namespace comminute::pbm
