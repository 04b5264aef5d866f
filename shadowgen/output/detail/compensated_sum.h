#pragma once

// Neumaier's compensated sum: the error stays near one rounding however many terms there
// are, so report totals do not depend on the scene's size.

#include <cmath>

namespace shadowgen::output::detail {

class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x)) {
      compensation_ += (sum_ - t) + x;
    } else {
      compensation_ += (x - t) + sum_;
    }
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace shadowgen::output::detail
