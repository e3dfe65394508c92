#pragma once
// Whether a teammate counts as in radio contact, from the raw per-tick link flag. A link near the
// edge of its range flickers (a parked car's gap, a wall's corner): judged tick by tick, a
// "lost contact" trigger would stop and restart a robot several times a second. As a real radio's
// link monitor does, contact is lost only after the link has been down for `loss_after_s`
// without a break, and restored only after it has been up for `restore_after_s`.
#include <map>
#include <string>

namespace autonomy::behavior {

struct ContactJudgeSettings {
  double loss_after_s = 2.0;     // >= 0; 0 judges every tick on its own
  double restore_after_s = 0.5;  // >= 0
};

class ContactJudge {
 public:
  explicit ContactJudge(ContactJudgeSettings settings = {});

  // The judgement for `teammate` at `time_s` (non-decreasing per teammate) given the raw flag.
  // A teammate seen for the first time takes its raw flag as it is.
  bool update(const std::string& teammate, double time_s, bool link_up);

 private:
  struct Track {
    bool judged = false;
    bool raw = false;
    double raw_since_s = 0.0;  // when the raw flag last changed
  };
  ContactJudgeSettings settings_;
  std::map<std::string, Track> tracks_;
};

}  // namespace autonomy::behavior
