// Copyright contactlaws authors.
//
// How a front-end asks the work it started to stop: a token that reads a
// flag the front-end owns (the command line's, set by SIGINT; a Python
// call's own, set when Ctrl-C reaches it). The work checks it between steps
// and reports what it did not finish as interrupted.

#ifndef CONTACTLAWS_APP_STOP_H_
#define CONTACTLAWS_APP_STOP_H_

#include <atomic>
#include <functional>

namespace contactlaws::app {

class StopToken {
 public:
  StopToken() = default;  // never asks to stop
  explicit StopToken(const std::atomic<bool>* flag) : flag_(flag) {}

  // As the library's should_stop callbacks take it (empty: never).
  std::function<bool()> Callback() const {
    if (!flag_) return {};
    return [flag = flag_] { return flag->load(std::memory_order_relaxed); };
  }

 private:
  const std::atomic<bool>* flag_ = nullptr;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_STOP_H_
