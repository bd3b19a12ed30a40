// The default broad phase (PCCD_BROAD_AUTO), chosen by measurement (README, "Broad
// phases"; tests/bench/bench_online.py and tests/bench/broad_phases.py). Speed only:
// every broad phase gives the same answers.
#pragma once

namespace pccd::broad {

// online: the pair comes from an on-line index (the stored side's trees exist already
// and are shared by every query); otherwise a scene's body pair, solved once.
inline bool choose_range(bool online) { return online; }

}  // namespace pccd::broad
