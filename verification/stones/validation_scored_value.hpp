#pragma once
// The model value of a scorable quantity (validation.hpp: scorable_quantities) from a variant's
// stored record, with the note that says why there is none (validation_findings.cpp).
#include <string>

#include "verification/stones/validation.hpp"
#include "verification/stones/validation_score.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

ScoredValue scored_value(const Record& variant, const std::string& key, const ValidationOptions& o);

}  // namespace stoneskip
