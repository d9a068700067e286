// Per-frame cost of the core: 640x480 in, preprocessing + estimation out (issue: <= 150 us).
// Frames are drawn before timing; only Tracker/Preprocessor/Estimator calls are timed.

#include <benchmark/benchmark.h>

#include <vector>

#include <opencv2/imgproc.hpp>

#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/tracker.hpp"

namespace {

using raypoint::core::FrameView;
using raypoint::core::PixelFormat;

// A dark disk circling over a mildly textured light background, 30 fps.
std::vector<cv::Mat> make_frames(cv::Size size, int count) {
    std::vector<cv::Mat> frames;
    cv::Mat background(size, CV_8UC3);
    cv::randu(background, cv::Scalar::all(180), cv::Scalar::all(230));
    cv::GaussianBlur(background, background, {0, 0}, 3.0);
    for (int i = 0; i < count; ++i) {
        cv::Mat frame = background.clone();
        const double angle = i * 0.08;
        const cv::Point centre(static_cast<int>(size.width * (0.5 + 0.2 * std::cos(angle))),
                               static_cast<int>(size.height * (0.5 + 0.2 * std::sin(angle))));
        cv::circle(frame, centre, size.height / 8, cv::Scalar(40, 30, 30), cv::FILLED, cv::LINE_AA);
        frames.push_back(frame);
    }
    return frames;
}

std::vector<cv::Mat> to_yuyv(const std::vector<cv::Mat>& frames) {
    std::vector<cv::Mat> out;
    for (const auto& bgr : frames) {
        cv::Mat yuv;
        cv::cvtColor(bgr, yuv, cv::COLOR_BGR2YUV);
        cv::Mat packed(bgr.rows, bgr.cols * 2, CV_8U);
        for (int y = 0; y < bgr.rows; ++y) {
            const auto* in = yuv.ptr<cv::Vec3b>(y);
            auto* row = packed.ptr<std::uint8_t>(y);
            for (int x = 0; x < bgr.cols; x += 2) {
                row[2 * x + 0] = in[x][0];
                row[2 * x + 1] = static_cast<std::uint8_t>((in[x][1] + in[x + 1][1]) / 2);
                row[2 * x + 2] = in[x + 1][0];
                row[2 * x + 3] = static_cast<std::uint8_t>((in[x][2] + in[x + 1][2]) / 2);
            }
        }
        out.push_back(packed);
    }
    return out;
}

FrameView view(const cv::Mat& frame, PixelFormat format, int width, long index) {
    return {frame.data, width, frame.rows, static_cast<int>(frame.step), format, index * 33333};
}

void run_tracker(benchmark::State& state, PixelFormat format) {
    const cv::Size size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    auto frames = make_frames(size, 64);
    if (format == PixelFormat::yuyv) frames = to_yuyv(frames);
    raypoint::core::Settings settings;
    settings.tracking.startup_seconds = 0.0;
    raypoint::core::Tracker tracker(settings);
    long index = 0;
    // Warm up into TRACKING, so the timed frames are the steady state of a tracked target.
    for (int i = 0; i < 32; ++i, ++index) {
        tracker.process(view(frames[index % frames.size()], format, size.width, index));
    }
    for (auto _ : state) {
        const auto result =
            tracker.process(view(frames[index % frames.size()], format, size.width, index));
        benchmark::DoNotOptimize(result);
        ++index;
    }
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_TrackerBgr(benchmark::State& state) {
    run_tracker(state, PixelFormat::bgr);
}
void BM_TrackerYuyv(benchmark::State& state) {
    run_tracker(state, PixelFormat::yuyv);
}

void BM_Preprocess(benchmark::State& state) {
    const cv::Size size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    const auto frames = make_frames(size, 8);
    raypoint::core::Preprocessor preprocessor{raypoint::core::PreprocessSettings{}};
    long index = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(preprocessor.process(
            view(frames[index % frames.size()], PixelFormat::bgr, size.width, index)));
        ++index;
    }
}

void BM_Estimator(benchmark::State& state) {
    raypoint::core::EstimatorSettings settings;
    settings.kind = static_cast<raypoint::core::EstimatorKind>(state.range(0));
    const auto frames = make_frames({640, 480}, 1);
    raypoint::core::Preprocessor preprocessor{raypoint::core::PreprocessSettings{}};
    preprocessor.process(view(frames[0], PixelFormat::bgr, 640, 0));
    auto estimator = raypoint::core::make_estimator(settings);
    // Start 4 px off the disk's centre, as after a frame of motion.
    const cv::Point2f start(0.7F * 160 - 4.0F, 0.5F * 120);
    for (auto _ : state) {
        benchmark::DoNotOptimize(estimator->estimate(preprocessor.edges(), start));
    }
    state.SetLabel(std::string(raypoint::core::to_string(settings.kind)));
}

}  // namespace

BENCHMARK(BM_TrackerBgr)->Args({640, 480})->Args({320, 240})->Args({1280, 720})->Args({1920, 1080});
BENCHMARK(BM_TrackerYuyv)->Args({640, 480})->Args({1280, 720});
BENCHMARK(BM_Preprocess)->Args({640, 480});
BENCHMARK(BM_Estimator)->DenseRange(0, 3);

BENCHMARK_MAIN();
