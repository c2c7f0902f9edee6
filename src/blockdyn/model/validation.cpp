#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "blockdyn/model/block_params.hpp"
#include "blockdyn/model/ground_motion.hpp"

namespace blockdyn {

namespace {
void require(bool ok, const std::string& field, const std::string& range, double v) {
  if (!ok) {
    std::ostringstream os;
    os << field << " = " << v << " is out of range: must be " << range;
    throw std::invalid_argument(os.str());
  }
}
bool finite(double v) { return std::isfinite(v); }
}  // namespace

void validate(const BlockParams& p) {
  require(finite(p.r) && p.r > 0.0, "r", "a finite number > 0", p.r);
  require(finite(p.mu) && p.mu >= 0.0, "mu", "a finite number >= 0", p.mu);
  require(finite(p.k) && p.k > 0.0, "k", "a finite number > 0", p.k);
}

void validate(const GroundMotion& g) {
  const GroundComponent* c[2] = {&g.horizontal, &g.vertical};
  const char* name[2] = {"ground.horizontal", "ground.vertical"};
  for (int i = 0; i < 2; ++i) {
    const std::string n = name[i];
    require(finite(c[i]->constant), n + ".constant", "finite", c[i]->constant);
    require(finite(c[i]->amplitude), n + ".amplitude", "finite", c[i]->amplitude);
    require(finite(c[i]->frequency) && c[i]->frequency >= 0.0, n + ".frequency", "finite and >= 0",
            c[i]->frequency);
    require(finite(c[i]->phase), n + ".phase", "finite", c[i]->phase);
    require(finite(c[i]->t_start) && c[i]->t_start >= 0.0, n + ".t_start", "finite and >= 0",
            c[i]->t_start);
    require(finite(c[i]->duration) && c[i]->duration >= 0.0, n + ".duration", "finite and >= 0",
            c[i]->duration);
  }
}

}  // namespace blockdyn
