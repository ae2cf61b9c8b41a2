#pragma once
// Runs one long operation (a reduction, a refinement) on a worker thread so the window never
// freezes. The UI thread polls progress and collects the result or the error message; cancelling
// makes the progress callback throw, which unwinds the worker.
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>
#include <variant>

namespace vl::ui {

// Thrown from the progress callback once cancellation was requested.
struct TaskCancelled {};

template <class Result> class BackgroundTask {
  public:
    using Progress = std::function<void(double)>;
    using Work = std::function<Result(const Progress&)>;
    using Outcome = std::variant<Result, std::string>; // the result or an error message

    ~BackgroundTask() { cancel(); }

    // Starts `work`; a previous run is cancelled and joined first.
    void start(std::string label, Work work) {
        cancel();
        label_ = std::move(label);
        progress_ = 0.0;
        started_ = std::chrono::steady_clock::now();
        {
            std::lock_guard lock(mutex_);
            outcome_.reset();
        }
        running_ = true;
        thread_ = std::jthread([this, work = std::move(work)](std::stop_token stop) {
            const Progress progress = [this, stop](double value) {
                if (stop.stop_requested()) throw TaskCancelled{};
                progress_ = value;
            };
            std::optional<Outcome> outcome;
            try {
                outcome.emplace(std::in_place_index<0>, work(progress));
            } catch (const TaskCancelled&) {
                outcome.reset();
            } catch (const std::exception& e) {
                outcome.emplace(std::in_place_index<1>, e.what());
            }
            {
                std::lock_guard lock(mutex_);
                // A run cancelled without waiting (requestCancel) finished after all: nobody wants it.
                if (stop.stop_requested()) outcome.reset();
                outcome_ = std::move(outcome);
            }
            running_ = false;
        });
    }

    // Cancels and waits for the worker to end.
    void cancel() {
        if (thread_.joinable()) {
            thread_.request_stop();
            thread_.join();
        }
        running_ = false;
    }

    // Cancels without waiting (the Cancel buttons): running() is false at once and the outcome is
    // dropped; the worker ends at its next progress call (or when its work ends, for work that never
    // reports progress) and is joined by the next start(), cancel() or the destructor.
    void requestCancel() {
        if (thread_.joinable()) thread_.request_stop();
        std::lock_guard lock(mutex_); // an outcome that arrived just before the click is dropped too
        outcome_.reset();
        running_ = false;
    }

    // Blocks until the current run ends (used by tests and the screenshot mode).
    void wait() {
        if (thread_.joinable()) thread_.join();
    }

    bool running() const { return running_; }
    double progress() const { return progress_; }
    // The time left, estimated from the progress so far (none before 2 % or for work without progress).
    std::optional<double> secondsLeft() const {
        const double p = progress_;
        if (!running_ || !(p >= 0.02 && p < 1.0)) return std::nullopt;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
        return elapsed * (1.0 - p) / p;
    }
    const std::string& label() const { return label_; }

    // The outcome of a finished run, once; empty while running, after a cancel, or when taken.
    std::optional<Outcome> take() {
        if (running_) return std::nullopt;
        std::lock_guard lock(mutex_);
        return std::exchange(outcome_, std::nullopt);
    }

  private:
    std::string label_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> running_{false};
    std::chrono::steady_clock::time_point started_{};
    std::mutex mutex_;
    std::optional<Outcome> outcome_;
    std::jthread thread_; // last member: joined before the others are destroyed
};

} // namespace vl::ui
