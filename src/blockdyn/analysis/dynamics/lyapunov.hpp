// SPDX-License-Identifier: Apache-2.0
#pragma once
// Largest Lyapunov exponent of a hybrid (event-driven) system by two-trajectory renormalisation
// (Benettin et al. 1980).
//
// The reference and the perturbed copy are integrated TOGETHER, as one hybrid system PairModel
// (state of twice the size, the union of both copies' events, each event switching only its own
// copy's mode). Two reasons:
//   - each copy still passes through its OWN events at its own times, so the effect of mode
//     switches on the separation (what a variational treatment puts into saltation matrices) is
//     contained in the two trajectories;
//   - both copies take the same steps, so their truncation errors are nearly equal and cancel in
//     the separation. Integrated independently (different adaptive step sequences) the errors
//     act as noise of the size of the tolerance on a separation d0, which biases a near-zero
//     exponent upwards (measured: 0.035 instead of ~0.003 for steady rocking at d0 = 1e-8).
//
// The separation is measured and renormalised back to d0 either
//   - Time:    at fixed time intervals, both states at the same time. Valid for the block
//              because its state never jumps at events (no impulsive impacts): only the vector
//              field switches, so the separation is continuous in time. A renormalisation is
//              postponed (by interval/1000, repeatedly) while the two copies are in different
//              modes (an event time lies between them).
//   - Section: at matching crossings of a Poincare section (the next crossing of each copy, in
//              the same direction), comparing the two crossing states. The copy is restarted
//              from the rescaled state together with the reference at the reference's crossing
//              (autonomous systems only). This removes the neutral along-flow component of the
//              separation. If the crossings stop corresponding (one copy crosses twice before the
//              other once, or not within max_gap), the copy is re-seeded from the reference
//              (counted in `resyncs`, no growth recorded for that leg).
// Estimate after n renormalisations: lambda_n = sum_i log(d_i / d_start_i) / (t_n - t_0).
//
// A model is used through an adapter providing the metric and the rescaling (which must leave a
// state consistent with its mode): BlockLyapunovAdapter in lyapunov_block.hpp, toy adapters in
// tests/analysis/dynamics/test_lyapunov.cpp.
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "blockdyn/simulation/simulation.hpp"

namespace blockdyn {

enum class LyapunovMethod { Time, Section };
const char* to_string(LyapunovMethod m);

struct LyapunovOptions {
  LyapunovMethod method = LyapunovMethod::Time;
  double t_start = 0.0;
  double t_end = 100.0;
  double d0 = 1e-8;            // separation right after each renormalisation (metric units)
  double interval = 0.5;       // Time: renormalisation interval
  double max_gap = 50.0;       // Section: the copies' corresponding crossings must lie within this time
  int max_deferrals = 100000;  // Time: give up if the modes never agree
  IntegratorOptions integrator;
};

void validate(const LyapunovOptions& o);

struct LyapunovSample {
  double t;         // reference time of the renormalisation
  double growth;    // log(d / d_start) of this leg
  double estimate;  // running exponent
};

enum class LyapunovStatus { Completed, ReferenceStopped, PerturbedStopped, Failed };
const char* to_string(LyapunovStatus s);

struct LyapunovResult {
  double exponent = 0;  // final running estimate
  double t_final = 0;   // reference time reached
  LyapunovStatus status = LyapunovStatus::Completed;
  std::string note;  // why the run stopped early, if it did
  long renormalisations = 0, deferrals = 0, resyncs = 0;
  double sum_log = 0;
  std::vector<LyapunovSample> history;
};

// Exponent over the part of the run after t_from: the growth accumulated after the last
// renormalisation at or before t_from, divided by the time since then. Removes the transient
// (e.g. the dissipative start of a settle-down orbit) that the running estimate only outgrows as 1/t.
inline double tail_exponent(const LyapunovResult& r, double t_from) {
  double t0 = -INFINITY, sum = 0;
  for (const auto& s : r.history) {
    if (s.t <= t_from) {
      t0 = s.t;
      sum = 0;
    } else {
      sum += s.growth;
    }
  }
  if (!std::isfinite(t0) || r.history.empty() || r.history.back().t <= t0) return NAN;
  return sum / (r.history.back().t - t0);
}

// Two copies of a hybrid model as one hybrid model. Events 0..NE-1 belong to copy a (the
// reference), NE..2NE-1 to copy b.
template <HybridModel M>
class PairModel {
 public:
  static constexpr std::size_t N = M::kDim;
  static constexpr std::size_t NE = M::kNumEvents;
  static constexpr std::size_t kDim = 2 * N;
  static constexpr std::size_t kNumEvents = 2 * NE;
  struct Mode {
    typename M::Mode a{}, b{};
  };
  using State = Vec<kDim>;
  using Half = Vec<N>;

  explicit PairModel(const M& m) : m_(m) {}

  static void split(const State& z, Half& a, Half& b) {
    for (std::size_t i = 0; i < N; ++i) {
      a[i] = z[i];
      b[i] = z[N + i];
    }
  }
  static State join(const Half& a, const Half& b) {
    State z;
    for (std::size_t i = 0; i < N; ++i) {
      z[i] = a[i];
      z[N + i] = b[i];
    }
    return z;
  }

  void rhs(double t, const Mode& md, const State& z, State& dz) const {
    Half a, b, da, db;
    split(z, a, b);
    m_.rhs(t, md.a, a, da);
    m_.rhs(t, md.b, b, db);
    dz = join(da, db);
  }
  void events(double t, const Mode& md, const State& z, std::array<double, kNumEvents>& g) const {
    Half a, b;
    split(z, a, b);
    std::array<double, NE> ga, gb;
    m_.events(t, md.a, a, ga);
    m_.events(t, md.b, b, gb);
    for (std::size_t i = 0; i < NE; ++i) {
      g[i] = ga[i];
      g[NE + i] = gb[i];
    }
  }
  void complete(const Mode& md, State& z) const {
    Half a, b;
    split(z, a, b);
    m_.complete(md.a, a);
    m_.complete(md.b, b);
    z = join(a, b);
  }
  // A breakpoint of the input is one for both copies.
  Transition<Mode> transition(double t, const Mode& md, State& z, int e) const {
    Half a, b;
    split(z, a, b);
    if (e == kBreakpoint) {
      const auto ta = m_.transition(t, md.a, a, e);
      const auto tb = m_.transition(t, md.b, b, e);
      z = join(a, b);
      return Transition<Mode>{Mode{ta.next, tb.next}, ta.stop || tb.stop, ta.kind};
    }
    const bool first = e < int(NE);
    last_copy_ = first ? 0 : 1;
    const auto tr = first ? m_.transition(t, md.a, a, e) : m_.transition(t, md.b, b, e - int(NE));
    z = join(a, b);
    Transition<Mode> out;
    out.next = md;
    (first ? out.next.a : out.next.b) = tr.next;
    out.stop = tr.stop;
    out.kind = tr.kind;
    return out;
  }
  // Chatter is resolved for the copy whose events chattered (the last one to switch).
  std::optional<Transition<Mode>> resolve_chatter(double t, const Mode& md, const State& z) const {
    Half a, b;
    split(z, a, b);
    const auto r = last_copy_ == 0 ? m_.resolve_chatter(t, md.a, a) : m_.resolve_chatter(t, md.b, b);
    if (!r) return std::nullopt;
    Transition<Mode> out;
    out.next = md;
    (last_copy_ == 0 ? out.next.a : out.next.b) = r->next;
    out.stop = r->stop;
    out.kind = r->kind;
    return out;
  }
  double step_hint(const Mode& md) const { return std::fmin(m_.step_hint(md.a), m_.step_hint(md.b)); }
  double next_breakpoint(double t, const Mode& md) const {
    return std::fmin(next_breakpoint_of(m_, t, md.a), next_breakpoint_of(m_, t, md.b));
  }
  State abs_tol_scale() const {
    const Half s = m_.abs_tol_scale();
    return join(s, s);
  }
  const M& model() const { return m_; }

 private:
  const M& m_;
  mutable int last_copy_ = 0;  // not shared: each estimator run owns its PairModel
};

// Adapter requirements (Model M, Adapter A):
//   double A::distance(const Mode& mr, const State& zr, const Mode& mp, const State& zp) const;
//   bool   A::compatible(const Mode& mr, const Mode& mp) const;   // same mode: may rescale
//   void   A::rescale(const Mode& mr, const State& zr, Mode& mp, State& zp, double s) const;
//          // zp <- zr + s (zp - zr), mode made consistent
//   void   A::perturb(const Mode& mr, const State& zr, double d, Mode& mp, State& zp) const;
//          // a perturbed copy at distance ~d (the initial direction)
//   bool   A::is_section_event(int event_index) const;
//   int    A::crossing_sign(const State& z) const;   // direction of a section crossing
template <HybridModel M, class A>
class LyapunovEstimator {
 public:
  using Mode = typename M::Mode;
  using State = Vec<M::kDim>;
  using Pair = PairModel<M>;
  static constexpr int NE = int(M::kNumEvents);

  // Renormalising two copies at equal times measures a separation that an impact makes jump by
  // O(1) whenever the copies' impact times differ: without saltation matrices the estimate is
  // meaningless for such models, so they are refused here.
  static_assert(!has_state_jumps<M>(),
                "LyapunovEstimator: this model's state jumps at events (impacts); the two-trajectory "
                "estimator is only valid for models whose state is continuous across events");

  LyapunovEstimator(const M& model, const A& adapter, LyapunovOptions opt) : model_(model), ad_(adapter), opt_(opt) {
    validate(opt_);
  }

  LyapunovResult run(Mode mr, State zr) const {
    model_.complete(mr, zr);
    Mode mp;
    State zp;
    ad_.perturb(mr, zr, opt_.d0, mp, zp);
    LyapunovResult res;
    res.history.reserve(1024);
    const double d_init = ad_.distance(mr, zr, mp, zp);
    if (!(d_init > 0) || !std::isfinite(d_init))
      throw std::invalid_argument("lyapunov: the initial perturbation is zero");
    if (opt_.method == LyapunovMethod::Time)
      run_time(mr, zr, mp, zp, d_init, res);
    else
      run_section(mr, zr, mp, zp, d_init, res);
    return res;
  }

 private:
  using PMode = typename Pair::Mode;
  using PState = typename Pair::State;

  struct Quiet final : Observer<Pair> {  // remembers which copy a stopping event belonged to
    int stopped_copy = -1;
    bool on_event(const Pair&, const EventInfo<PMode, Pair::kDim>& e) override {
      if (e.stop) stopped_copy = e.index < NE ? 0 : 1;
      return true;
    }
  };

  // Stops once both copies crossed the section (or the crossings stopped corresponding).
  struct Crossings final : Observer<Pair> {
    Crossings(const A* a, double gap) : ad(a), max_gap(gap) {}
    const A* ad;
    double max_gap;
    int stopped_copy = -1;
    int count[2] = {0, 0};
    double t[2] = {0, 0};
    State z[2]{};
    Mode m[2]{};
    bool mismatch = false;
    void reset() {
      count[0] = count[1] = 0;
      mismatch = false;
      stopped_copy = -1;
    }
    bool on_segment(const Pair&, const DenseSegment<Pair::kDim>&, double, double t1, const PMode&) override {
      for (int c = 0; c < 2; ++c)
        if (count[c] == 1 && count[1 - c] == 0 && t1 - t[c] > max_gap) mismatch = true;
      return !mismatch;
    }
    bool on_event(const Pair&, const EventInfo<PMode, Pair::kDim>& e) override {
      const int c = e.index < NE ? 0 : 1;
      if (e.stop) {
        stopped_copy = c;
        return false;
      }
      if (!ad->is_section_event(e.index % NE)) return true;
      if (++count[c] > 1) {
        mismatch = true;  // this copy crossed twice before the other once
        return false;
      }
      t[c] = e.t;
      State a, b;
      Pair::split(e.z, a, b);
      z[c] = c == 0 ? a : b;
      m[c] = c == 0 ? e.to.a : e.to.b;
      return count[1 - c] == 0;
    }
  };

  void record(LyapunovResult& res, double t, double growth) const {
    res.sum_log += growth;
    ++res.renormalisations;
    const double span = t - opt_.t_start;
    res.exponent = span > 0 ? res.sum_log / span : 0.0;
    res.history.push_back({t, growth, res.exponent});
  }

  void run_time(Mode mr, State zr, Mode mp, State zp, double d_start, LyapunovResult& res) const {
    const Pair pair(model_);
    double t = opt_.t_start;
    PMode md{mr, mp};
    PState z = Pair::join(zr, zp);
    Simulation<Pair> sim(pair, opt_.integrator, t, md, z);
    Quiet q;
    double t_target = std::fmin(t + opt_.interval, opt_.t_end);
    int deferred = 0;
    while (t < opt_.t_end) {
      const RunStatus st = sim.advance_from(t, md, z, t_target, q);
      res.t_final = t;
      if (st != RunStatus::ReachedEnd) return stop(res, q.stopped_copy, st);
      if (!ad_.compatible(md.a, md.b) && t < opt_.t_end) {
        // Different modes (an event lies between the two): try again a little later.
        ++res.deferrals;
        if (++deferred > opt_.max_deferrals) {
          res.status = LyapunovStatus::Failed;
          res.note = "modes of the two trajectories never agreed";
          return;
        }
        t_target = std::fmin(t + 1e-3 * opt_.interval, opt_.t_end);
        continue;
      }
      deferred = 0;
      Pair::split(z, zr, zp);
      const double d = ad_.distance(md.a, zr, md.b, zp);
      record(res, t, std::log(d / d_start));
      ad_.rescale(md.a, zr, md.b, zp, opt_.d0 / d);
      d_start = ad_.distance(md.a, zr, md.b, zp);
      z = Pair::join(zr, zp);
      t_target = std::fmin(t + opt_.interval, opt_.t_end);
    }
  }

  void run_section(Mode mr, State zr, Mode mp, State zp, double d_start, LyapunovResult& res) const {
    const Pair pair(model_);
    double t = opt_.t_start;
    PMode md{mr, mp};
    PState z = Pair::join(zr, zp);
    Simulation<Pair> sim(pair, opt_.integrator, t, md, z);
    Crossings cr(&ad_, opt_.max_gap);
    while (t < opt_.t_end) {
      cr.reset();
      const RunStatus st = sim.advance_from(t, md, z, opt_.t_end, cr);
      res.t_final = t;
      if (st == RunStatus::ReachedEnd) return;
      if (st != RunStatus::ObserverStop || cr.stopped_copy >= 0) return stop(res, cr.stopped_copy, st);
      const bool both = cr.count[0] == 1 && cr.count[1] == 1;
      if (cr.mismatch || !both || ad_.crossing_sign(cr.z[0]) != ad_.crossing_sign(cr.z[1])) {
        // The crossing sequences no longer correspond: re-seed the copy from the reference.
        ++res.resyncs;
        Pair::split(z, zr, zp);
        ad_.perturb(md.a, zr, opt_.d0, md.b, zp);
        z = Pair::join(zr, zp);
        d_start = ad_.distance(md.a, zr, md.b, zp);
        continue;
      }
      const double d = ad_.distance(cr.m[0], cr.z[0], cr.m[1], cr.z[1]);
      record(res, cr.t[0], std::log(d / d_start));
      if (ad_.compatible(cr.m[0], cr.m[1])) {
        // Restart both at the reference's crossing (autonomous system), the copy rescaled.
        zr = cr.z[0];
        zp = cr.z[1];
        md.a = cr.m[0];
        md.b = cr.m[1];
        ad_.rescale(md.a, zr, md.b, zp, opt_.d0 / d);
        d_start = ad_.distance(md.a, zr, md.b, zp);
        t = cr.t[0];
        z = Pair::join(zr, zp);
      } else {
        ++res.deferrals;  // different modes at the crossings: measure on from here unscaled
        d_start = d;
      }
    }
  }

  void stop(LyapunovResult& res, int copy, RunStatus rs) const {
    res.status = copy == 1 ? LyapunovStatus::PerturbedStopped : LyapunovStatus::ReferenceStopped;
    // Appended piece by piece: GCC 12 warns of a false array bound in the concatenated temporary.
    res.note = copy == 1 ? "perturbed" : "reference";
    res.note += " trajectory stopped: ";
    res.note += to_string(rs);
  }

  const M& model_;
  const A& ad_;
  LyapunovOptions opt_;
};

}  // namespace blockdyn
