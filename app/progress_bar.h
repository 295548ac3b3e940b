// A bar on stderr for long commands (bench, record): drawn only when stderr is
// a terminal, so that logs and tests see none of it.
#pragma once
#include <unistd.h>

#include <cstdio>

namespace gridcull {

class ProgressBar {
public:
    explicit ProgressBar(long long total) : total_(total), enabled_(::isatty(2) != 0) {}
    void step() {
        ++done_;
        if (!enabled_) return;
        const int percent = int(done_ * 100 / total_);
        if (percent == last_percent_) return;
        last_percent_ = percent;
        const int width = 40, filled = percent * width / 100;
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled,
                     "########################################", width - filled, "", percent);
        if (done_ == total_) std::fputs("\n", stderr);
        std::fflush(stderr);
    }

private:
    long long total_;
    long long done_ = 0;
    int last_percent_ = -1;
    bool enabled_;
};

}  // namespace gridcull
