/**
 * @file progress.hpp  How far a long integration has come, on a stream (stderr), at most a few times a
 * second: "integrating: t = 3.2 of 10 (32 %), 1.5 s". On a terminal one line is rewritten in place and
 * cleared at the end; elsewhere (a log, `--progress` into a pipe) a line is written at most once a second.
 */
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>

namespace eomgen {

/// Where progress goes: nowhere, whole lines (a file, a pipe) or one line rewritten in place (a terminal).
enum class ProgressStyle { None, Lines, Terminal };

class ProgressMeter {
   public:
    using Clock = std::chrono::steady_clock;

    /// `out` may be null (no messages). Nothing is written before `quiet_for` has passed: short runs stay silent.
    ProgressMeter(std::ostream* out, ProgressStyle style, double t_end, double quiet_for = 1.0)
        : out_(style == ProgressStyle::None ? nullptr : out),
          style_(style),
          t_end_(t_end),
          start_(Clock::now()),
          next_(start_ + seconds(quiet_for)) {}

    ProgressMeter(const ProgressMeter&) = delete;
    ProgressMeter& operator=(const ProgressMeter&) = delete;
    ~ProgressMeter() { finish(); }

    bool active() const { return out_ != nullptr; }

    /// The integration has reached t (one read of the clock; callers in an inner loop thin their calls).
    void at(double t) {
        if (!out_) return;
        const Clock::time_point now = Clock::now();
        if (now < next_) return;
        next_ = now + seconds(style_ == ProgressStyle::Terminal ? 0.25 : 1.0);
        const double elapsed = std::chrono::duration<double>(now - start_).count();
        const double percent = t_end_ > 0 ? std::clamp(100 * t / t_end_, 0.0, 100.0) : 0;
        char line[160];
        std::snprintf(line, sizeof line, "integrating: t = %.6g of %.6g (%.0f %%), %.1f s", t, t_end_, percent,
                      elapsed);
        if (style_ == ProgressStyle::Terminal) {
            *out_ << '\r' << line << "\033[K" << std::flush;
            shown_ = true;
        } else {
            *out_ << line << '\n' << std::flush;
        }
    }

    /// Clears the line rewritten in place (called by the destructor too).
    void finish() {
        if (out_ && shown_) *out_ << "\r\033[K" << std::flush;
        shown_ = false;
    }

   private:
    static Clock::duration seconds(double s) {
        return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
    }

    std::ostream* out_;
    ProgressStyle style_;
    double t_end_;
    Clock::time_point start_, next_;
    bool shown_ = false;
};

}  // namespace eomgen
