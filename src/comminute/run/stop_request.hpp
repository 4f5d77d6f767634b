#pragma once
// Clean stop on SIGINT (Ctrl-C) and SIGTERM: while a StopRequest exists, the signal only sets a
// flag; the run loop checks requested() between steps, writes a checkpoint and exits with
// exit_code() (128 + signal number: 130 for SIGINT, 143 for SIGTERM). A second signal while the
// first is being handled ends the program at once (the default action). The previous handlers
// are restored when the StopRequest is destroyed. One StopRequest at a time.
namespace comminute::run {

class StopRequest {
 public:
  StopRequest();
  ~StopRequest();
  StopRequest(const StopRequest&) = delete;
  StopRequest& operator=(const StopRequest&) = delete;

  bool requested() const;
  int signal_number() const;  // 0 when none arrived
  int exit_code() const { return 128 + signal_number(); }
  const char* signal_name() const;  // "SIGINT", "SIGTERM" or ""
};

}  // namespace comminute::run
