#include "background_jobs.h"

#include <utility>

namespace paver::studio {

BackgroundJobs::~BackgroundJobs() {
  stop_all();
  jobs_.clear();  // each jthread joins as it goes
}

void BackgroundJobs::start(std::function<void(std::stop_token)> job) {
  stop_all();
  reap();
  auto done = std::make_shared<std::atomic<bool>>(false);
  std::jthread thread([job = std::move(job), done](std::stop_token stop) {
    job(stop);
    done->store(true);
  });
  jobs_.push_back({std::move(thread), std::move(done)});
}

void BackgroundJobs::stop_all() {
  for (Job& job : jobs_) job.thread.request_stop();
}

void BackgroundJobs::reap() {
  std::erase_if(jobs_, [](const Job& job) { return job.done->load(); });  // joins: already finished
}

}  // namespace paver::studio
