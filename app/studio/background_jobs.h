#pragma once
// Jobs on threads of their own whose results the UI may stop wanting (the design changed again,
// another surface was opened). The UI thread never waits for one: an unwanted job is asked to
// stop through its stop_token and its thread is joined once it has finished by itself. Only the
// destructor, at exit, waits.
#include <atomic>
#include <functional>
#include <memory>
#include <stop_token>
#include <thread>
#include <vector>

namespace paver::studio {

class BackgroundJobs {
public:
  BackgroundJobs() = default;
  BackgroundJobs(const BackgroundJobs&) = delete;
  BackgroundJobs& operator=(const BackgroundJobs&) = delete;
  ~BackgroundJobs();

  // Runs job(stop) on a new thread; jobs still running are asked to stop first.
  void start(std::function<void(std::stop_token)> job);
  void stop_all();  // asks every job to stop; they finish on their own
  void reap();      // joins the threads that have finished

private:
  struct Job {
    std::jthread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  std::vector<Job> jobs_;
};

}  // namespace paver::studio
