#pragma once
// The unit of a table column, read from its name. Columns carry their unit as a suffix
// ("t_s", "entry_speed_m_s", "energy_J", "wx_deg_s"); a name without a unit suffix is a count, a
// flag, an index or a ratio, and its unit is "1". Every stored table writes these beside its
// column names (tools/io/hdf5_file.hpp, attribute `units`), so a reader in another language need
// not parse names. Names whose unit depends on their table ("value", "error", "x", "lo", ...)
// have no unit of their own: column_unit returns "" for them and their writer names the unit.
#include <string>

namespace stoneskip {

// "m/s" for "entry_speed_m_s", "1" for "bounces", "" for a name whose unit its table must give.
std::string column_unit(const std::string& name);

}  // namespace stoneskip
