// Steady state does not allocate (estimator.hpp, tracker.hpp): global operator new is replaced
// by a counting version for this whole executable; it counts only while `counting` is set.

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "frames.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/tracker.hpp"
#include "shapes.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void* allocate(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* allocate_aligned(std::size_t size, std::align_val_t alignment) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
    const auto align = static_cast<std::size_t>(alignment);
    const std::size_t rounded = (size + align - 1) / align * align;
    if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) {
    return allocate(size);
}
void* operator new[](std::size_t size) {
    return allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
    return operator new(size, tag);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return allocate_aligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return allocate_aligned(size, alignment);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}

namespace raypoint::core {
namespace {

// Counts the allocations `work` makes.
template <typename Work>
long allocations_during(Work&& work) {
    allocations = 0;
    counting = true;
    work();
    counting = false;
    return allocations.load();
}

TEST(NoAllocation, TheCounterCounts) {
    // The replacement is in effect: a vector's growth is seen (else every test here is void).
    std::vector<int> grown;
    EXPECT_GE(allocations_during([&] { grown.resize(1000); }), 1);
    EXPECT_EQ(allocations_during([] {}), 0);
}

TEST(NoAllocation, EstimateAfterTheFirstCallOnTheSameSize) {
    const test::Shape disk = test::disk();
    const test::Hand hand = test::hand();
    for (const EstimatorKind kind : {EstimatorKind::ray, EstimatorKind::iterative_ray,
                                     EstimatorKind::iterative_ny_ray, EstimatorKind::raster}) {
        for (const AreaMode mode : {AreaMode::refined, AreaMode::blocks}) {
            EstimatorSettings settings;
            settings.kind = kind;
            settings.area_mode = mode;
            auto estimator = make_estimator(settings);
            estimator->estimate(disk.edges, {80.0F, 60.0F});  // warm-up
            const long count = allocations_during([&] {
                estimator->estimate(disk.edges, {70.0F, 55.0F});
                estimator->estimate(hand.shape.edges, hand.fingertips[2]);
                estimator->estimate(hand.shape.edges, hand.palm);
            });
            EXPECT_EQ(count, 0) << to_string(kind) << (mode == AreaMode::blocks ? " blocks" : "");
        }
    }
}

TEST(NoAllocation, TrackerProcessInSteadyState) {
    // 40 frames of a disk moving on 640x480 BGR, built beforehand; 20 to warm up (the tracker
    // is tracking by then), 20 counted.
    constexpr int frames = 40;
    std::vector<cv::Mat> images;
    for (int i = 0; i < frames; ++i)
        images.push_back(test::noisy_disk(i, {100 + 12 * i, 240}, 50));
    Settings settings;
    settings.tracking.startup_seconds = 0.1;
    settings.tracking.search_threshold = 19200.0;  // see test_tracker.cpp
    Tracker tracker(settings);
    const auto view = [&](int i) {
        return test::bgr_view(images[static_cast<std::size_t>(i)], Timestamp{i} * 33'333);
    };
    for (int i = 0; i < 20; ++i)
        tracker.process(view(i));
    std::vector<FrameResult> results(frames);  // reserved: the loop below only assigns
    const long count = allocations_during([&] {
        for (int i = 20; i < frames; ++i)
            results[static_cast<std::size_t>(i)] = tracker.process(view(i));
    });
    for (int i = 20; i < frames; ++i) {
        ASSERT_EQ(results[static_cast<std::size_t>(i)].state, TrackerState::tracking)
            << "frame " << i;
    }
    EXPECT_EQ(count, 0);
}

}  // namespace
}  // namespace raypoint::core
