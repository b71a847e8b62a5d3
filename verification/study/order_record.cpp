#include "verification/study/order_record.hpp"

#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {


Record& store_order_fit(Record& parent, const std::string& key, const OrderFit& fit, const OrderJudgement& j) {
  Record& r = parent.child(key);
  r.set("valid", fit.valid);
  r.set("order", fit.order);
  r.set("order_low", fit.order_low);
  r.set("order_high", fit.order_high);
  r.set("points", fit.points);
  r.set("r_squared", fit.r_squared);
  r.set("constant", fit.constant);
  if (!fit.problem.empty()) r.set("problem", fit.problem);
  r.set_table("pairwise", value_list(fit.pairwise, "order"));
  Record in;
  in.set("valid", fit.valid);
  in.set("order", fit.order);
  in.set("order_low", fit.order_low);
  in.set("order_high", fit.order_high);
  in.set("points", fit.points);
  in.set("expected_order", j.expected_order);
  in.set("tolerance", j.tolerance);
  in.set("minimum_order", j.minimum_order);
  decide_verdict(r, "verdict", "order_fit", in, judge_order(fit, j).reason);
  return r;
}

OrderFit stored_order_fit(const Record& r) {
  OrderFit f;
  f.valid = r.flag("valid");
  f.order = r.number("order");
  f.order_low = r.number("order_low");
  f.order_high = r.number("order_high");
  f.points = static_cast<int>(r.number("points"));
  f.r_squared = r.number("r_squared");
  f.constant = r.number("constant");
  if (r.has_text("problem")) f.problem = r.text("problem");
  f.pairwise = list_values(r.table("pairwise"));
  return f;
}

OrderJudgement stored_judgement(const Record& v) {
  OrderJudgement j;
  j.expected_order = v.number("expected_order");
  j.tolerance = v.number("tolerance");
  j.minimum_order = v.number("minimum_order");
  return j;
}

Table value_list(const std::vector<double>& values, const std::string& column) {
  Table t;
  t.columns = {column};
  t.values = values;
  // Lists under the default name are the studies' grid sizes, step counts and σ fractions:
  // dimensionless. A named column ("dt_s") carries its unit in its name.
  if (column == "value") t.units = {"1"};
  return t;
}

std::vector<double> list_values(const Table& t) { return t.values; }

}  // namespace stoneskip
