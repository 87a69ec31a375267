#include "service/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace gem::kiosk {

double quantile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    // Nearest rank: the smallest value with at least p of the list at or below it.
    const double rank = std::ceil(p * static_cast<double>(values.size()));
    const auto i = static_cast<std::size_t>(std::max(rank, 1.0)) - 1;
    return values[std::min(i, values.size() - 1)];
}

void FrameStats::add(const FrameRecord& record) {
    ++total_;
    if (!record.drawn) {
        ++shown_again_;
        return;
    }
    if (record.probing) {
        ++while_probing_;
        return;
    }
    frames_.push_back(record);
    if (max_records_ > 0 && frames_.size() > max_records_) frames_.pop_front();
}

namespace {

std::string describe(const char* what, const std::vector<double>& v) {
    char line[160];
    std::snprintf(line, sizeof line, "%s ms p50 %.1f p90 %.1f p99 %.1f max %.1f", what,
                  quantile(v, 0.5), quantile(v, 0.9), quantile(v, 0.99), quantile(v, 1.0));
    return line;
}

}  // namespace

std::string FrameStats::summary() const {
    if (frames_.empty()) {
        return while_probing_ > 0 ? std::to_string(while_probing_) +
                                        " frames, all drawn while the method probe measured"
                                  : "no frames";
    }
    std::vector<double> draw;
    std::vector<double> moving;
    std::vector<double> still;
    std::vector<double> interval;
    std::vector<double> latency;
    for (const FrameRecord& f : frames_) {
        draw.push_back(f.draw_ms);
        (f.still < 0 ? moving : still).push_back(f.draw_ms);
        if (f.interval_ms > 0.0) interval.push_back(f.interval_ms);
        if (f.latency_ms >= 0.0) latency.push_back(f.latency_ms);
    }
    const double span_s =
        frames_.back().start_s + frames_.back().draw_ms / 1000.0 - frames_.front().start_s;
    char head[160];
    std::snprintf(head, sizeof head, "%zu frames in %.1f s: %.2f frames/s; ", frames_.size(),
                  span_s, span_s > 0.0 ? static_cast<double>(frames_.size()) / span_s : 0.0);
    std::string s = head;
    if (static_cast<long>(frames_.size()) < total_ - shown_again_ - while_probing_) {
        s = std::to_string(total_ - shown_again_ - while_probing_) + " frames, the last " + s;
    }
    s += describe("draw", draw);
    if (!moving.empty() && !still.empty()) {
        s += "; " +
             describe(("moving (" + std::to_string(moving.size()) + ") draw").c_str(), moving);
        s += "; " +
             describe(("still view (" + std::to_string(still.size()) + ") draw").c_str(), still);
    }
    if (!interval.empty()) s += "; " + describe("interval", interval);
    if (!latency.empty()) {
        s += "; " + describe("input-to-frame", latency) + " (" + std::to_string(latency.size()) +
             " frames with new input)";
    }
    if (shown_again_ > 0) {
        s += "; " + std::to_string(shown_again_) + " more shown again undrawn (a settled view)";
    }
    if (while_probing_ > 0) {
        s += "; " + std::to_string(while_probing_) + " more drawn while the method probe measured";
    }
    return s;
}

bool FrameStats::write_csv(const std::string& path, std::string& error) const {
    std::ofstream out(path);
    if (!out) {
        error = "cannot write " + path;
        return false;
    }
    out << "frame,start_s,draw_ms,interval_ms,latency_ms,streaming_ms,still\n";
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        const FrameRecord& f = frames_[i];
        out << i << ',' << f.start_s << ',' << f.draw_ms << ',' << f.interval_ms << ','
            << f.latency_ms << ',' << f.streaming_ms << ',' << f.still << '\n';
    }
    out.flush();
    if (!out) {
        error = "cannot write " + path + " (disk full?)";
        return false;
    }
    return true;
}

}  // namespace gem::kiosk
