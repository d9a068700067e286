// SPDX-License-Identifier: MIT
#include "click_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "input_error.hpp"

namespace raypoint::daemon {
namespace {

std::string percent(int part, int whole) {
    if (whole == 0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%% (%d/%d)", 100.0 * part / whole, part, whole);
    return text;
}

std::string number(double value, const char* format) {
    if (std::isnan(value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

int order(const std::string& group) {
    if (group == "all") return 0;
    if (group == "target" || group.starts_with("target (")) return 1;
    if (group.starts_with("motion=")) return 3;
    if (group.find('=') != std::string::npos) return 2;
    return 4;
}

}  // namespace

void print_tallies(std::FILE* out, const Tallies& tallies) {
    std::vector<std::string> groups;
    for (const auto& entry : tallies)
        groups.push_back(entry.first);
    std::stable_sort(groups.begin(), groups.end(),
                     [](const auto& a, const auto& b) { return order(a) < order(b); });
    std::fprintf(out,
                 "| group | pushes | pressed | click recall | drag recall | precision | median "
                 "latency (ms) | median offset (px) | non-push motion (min) | false clicks | "
                 "false / min |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& group : groups) {
        const Tally& t = tallies.at(group);
        std::fprintf(out, "| %s | %d | %s | %s | %s | %s | %s | %s | %s | %d | %s |\n",
                     group.c_str(), t.gestures(), percent(t.pushes_pressed, t.gestures()).c_str(),
                     percent(t.clicks_found, t.clicks).c_str(),
                     percent(t.drags_found, t.drags).c_str(), percent(t.matched, t.presses).c_str(),
                     number(median(t.latencies) * 1000, "%.0f").c_str(),
                     number(median(t.offsets), "%.1f").c_str(),
                     number(t.motion_seconds / 60, "%.1f").c_str(), t.false_clicks,
                     number(t.false_per_minute(), "%.2f").c_str());
    }
}

void print_gestures(std::FILE* out, const Tallies& tallies) {
    const Tally none;
    const Tally& all = tallies.contains("all") ? tallies.at("all") : none;
    std::fprintf(out,
                 "| gesture | count | recognised | taken for a left click | median latency (ms) "
                 "|\n|---|---|---|---|---|\n");
    auto row = [&](const std::string& name, const GestureTally& g) {
        std::fprintf(out, "| %s | %d | %s | %s | %s |\n", name.c_str(), g.count,
                     percent(g.found, g.count).c_str(), percent(g.as_left, g.count).c_str(),
                     number(median(g.latencies) * 1000, "%.0f").c_str());
    };
    const std::pair<const char*, GestureTally Tally::*> rows[] = {
        {"right click", &Tally::right},
        {"double click", &Tally::double_click},
        {"scroll", &Tally::scroll}};
    for (const auto& [name, member] : rows) {
        row(name, all.*member);
        // By what makes the gesture, where the set holds both: a hand and a ball miss for
        // different reasons (a ball's shaded side against dark furniture has no edge).
        for (const char* target : {"hand", "sphere"}) {
            const auto by = tallies.find(std::string("target=") + target);
            if (by != tallies.end() && (by->second.*member).count > 0 &&
                (by->second.*member).count < (all.*member).count)
                row(std::string(name) + " (" + target + ")", by->second.*member);
        }
    }
    std::fprintf(out, "| left click or drag taken for another gesture | %d | - | %s | - |\n",
                 all.gestures(), percent(all.left_as_other, all.gestures()).c_str());
    std::fprintf(out, "| wheel steps in non-push motion | %d | - | - | - |\n", all.false_wheel);
    std::fprintf(out,
                 "| approaches as fast as a push in non-push motion, pressed | %d | %s | - | - |\n",
                 all.approaches, percent(all.approaches_pressed, all.approaches).c_str());
}

void print_sweep(std::FILE* out, const std::vector<SweepPoint>& points) {
    std::fprintf(out,
                 "| series | setting | target pushes pressed | false clicks / min |\n"
                 "|---|---|---|---|\n");
    for (const SweepPoint& p : points) {
        std::fprintf(out, "| %s | %s | %.1f%% | %.2f |\n", p.series.c_str(), p.label.c_str(),
                     100 * p.recall, p.false_per_minute);
    }
}

void plot_sweep(const std::string& path, const std::vector<SweepPoint>& points) {
    const cv::Size size(960, 600);
    const cv::Rect area(90, 40, 600, 480);
    cv::Mat image(size, CV_8UC3, cv::Scalar(255, 255, 255));
    double max_false = 0.5;
    double min_recall = 0.5;
    for (const SweepPoint& p : points) {
        max_false = std::max(max_false, p.false_per_minute);
        min_recall = std::min(min_recall, std::floor(p.recall * 10) / 10);
    }
    max_false = std::ceil(max_false * 2) / 2;
    auto at = [&](double false_per_minute, double recall) {
        const double x = area.x + area.width * false_per_minute / max_false;
        const double y = area.y + area.height * (1 - (recall - min_recall) / (1 - min_recall));
        return cv::Point(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
    };
    const cv::Scalar grey(200, 200, 200);
    const cv::Scalar black(0, 0, 0);
    const int font = cv::FONT_HERSHEY_SIMPLEX;
    for (int i = 0; i <= 5; ++i) {
        const double f = max_false * i / 5;
        cv::line(image, at(f, min_recall), at(f, 1), grey);
        cv::putText(image, number(f, "%.2f"), at(f, min_recall) + cv::Point(-15, 20), font, 0.4,
                    black);
        const double r = min_recall + (1 - min_recall) * i / 5;
        cv::line(image, at(0, r), at(max_false, r), grey);
        cv::putText(image, number(100 * r, "%.0f%%"), at(0, r) + cv::Point(-50, 5), font, 0.4,
                    black);
    }
    // The targets: recall >= 95% at <= 0.1 false clicks a minute.
    cv::rectangle(image, at(0, 1), at(std::min(0.1, max_false), 0.95), cv::Scalar(200, 240, 200),
                  cv::FILLED);
    cv::rectangle(image, area, black);
    cv::putText(image, "false clicks per minute of non-push motion",
                {area.x + 120, size.height - 25}, font, 0.5, black);
    cv::putText(image, "recall: pushes >= 15% closer within 0.6 s that pressed", {area.x, 25}, font,
                0.5, black);
    const cv::Scalar colours[] = {{200, 60, 30},  {30, 140, 30}, {30, 30, 200},
                                  {160, 30, 160}, {0, 140, 200}, {90, 90, 90}};
    std::map<std::string, std::vector<const SweepPoint*>> series;
    std::vector<std::string> names;
    for (const SweepPoint& p : points) {
        if (!series.contains(p.series)) names.push_back(p.series);
        series[p.series].push_back(&p);
    }
    for (std::size_t s = 0; s < names.size(); ++s) {
        const cv::Scalar colour = colours[s % std::size(colours)];
        const auto& list = series[names[s]];
        for (std::size_t i = 0; i < list.size(); ++i) {
            const cv::Point p = at(list[i]->false_per_minute, list[i]->recall);
            cv::circle(image, p, 4, colour, cv::FILLED, cv::LINE_AA);
            if (i > 0) {
                cv::line(image, at(list[i - 1]->false_per_minute, list[i - 1]->recall), p, colour,
                         1, cv::LINE_AA);
            }
            cv::putText(image, list[i]->label, p + cv::Point(5, -5), font, 0.3, colour);
        }
        const cv::Point key(area.x + area.width + 15, area.y + 20 + 22 * static_cast<int>(s));
        cv::circle(image, key, 4, colour, cv::FILLED, cv::LINE_AA);
        cv::putText(image, names[s], key + cv::Point(10, 5), font, 0.4, colour);
    }
    if (!cv::imwrite(path, image)) throw InputError(path + ": cannot write the plot (PNG)");
}

}  // namespace raypoint::daemon
