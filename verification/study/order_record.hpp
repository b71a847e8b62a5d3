#pragma once
// Order fits and their verdicts as stored findings: the fit's numbers (order, interval, points,
// pairwise orders) and a verdict record (rule "order_fit") that keeps the rule's inputs, so the
// verdict can be decided again from data.h5 alone (reports' consistency test does).
#include <string>
#include <vector>

#include "verification/convergence/order_fit.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

// Writes child `key` of `parent`: order, order_low, order_high, points, r_squared, valid, the
// pairwise orders (table "pairwise": order) and the verdict (child "verdict"). Returns the child.
Record& store_order_fit(Record& parent, const std::string& key, const OrderFit& fit, const OrderJudgement& judgement);

// The fit as stored (for deciding again).
OrderFit stored_order_fit(const Record& fit_record);
// The drift of the local order as stored, in a fit record or a verdict's inputs (shape_tested,
// curved, local_order_coarse, local_order_fine; records written before them have none, and leave
// `fit` as it was).
void read_order_shape(const Record& r, OrderFit& fit);
OrderJudgement stored_judgement(const Record& verdict_record);

// A list of numbers as a one-column table ("value").
Table value_list(const std::vector<double>& values, const std::string& column = "value");
std::vector<double> list_values(const Table& t);

}  // namespace stoneskip
