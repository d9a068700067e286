// SPDX-License-Identifier: MIT
#include "raypoint/capture/jpeg_decoder.hpp"

// libjpeg's header needs size_t and FILE declared first.
#include <cstdio>
// clang-format off
#include <jpeglib.h>
#include <jerror.h>
// clang-format on

#include <csetjmp>
#include <cstring>
#include <new>
#include <stdexcept>

namespace raypoint::daemon {

// libjpeg reports fatal errors through error_exit, which must not return: it jumps back into
// decode() (libjpeg's documented way; no C++ object with a destructor lives between the two).
struct JpegState {
    jpeg_decompress_struct info{};
    jpeg_error_mgr errors{};
    std::jmp_buf jump{};
    bool truncated = false;  // "premature end of data": a frame cut short, e.g. on USB
    char message[JMSG_LENGTH_MAX] = {};
};

namespace {

JpegState& state_of(j_common_ptr info) {
    return *static_cast<JpegState*>(info->client_data);
}

[[noreturn]] void on_error(j_common_ptr info) {
    JpegState& state = state_of(info);
    (*info->err->format_message)(info, state.message);
    std::longjmp(state.jump, 1);
}

// Warnings (level -1) about corrupt data are not printed: the camera sends the next frame in
// 33 ms. Only a truncated frame is refused; cheap cameras add stray bytes to every frame, and
// refusing those would refuse the camera.
void on_message(j_common_ptr info, int level) {
    if (level == -1 && info->err->msg_code == JWRN_JPEG_EOF) state_of(info).truncated = true;
}

}  // namespace

JpegDecoder::JpegDecoder(cv::Size least) : state_(std::make_unique<JpegState>()), least_(least) {
    JpegState& state = *state_;
    state.info.err = jpeg_std_error(&state.errors);
    state.errors.error_exit = on_error;
    state.errors.emit_message = on_message;
    state.info.client_data = &state;
    if (setjmp(state.jump) != 0) {
        throw std::runtime_error(std::string("jpeg_create_decompress: ") + state.message);
    }
    jpeg_create_decompress(&state.info);
}

JpegDecoder::~JpegDecoder() {
    jpeg_destroy_decompress(&state_->info);
}

int JpegDecoder::scale_for(cv::Size frame, cv::Size least) noexcept {
    // libjpeg's output size at n/8 is the input size times n / 8, rounded up.
    const auto scaled = [](int size, int n) { return (size * n + 7) / 8; };
    for (int n = 1; n < 8; ++n) {
        if (scaled(frame.width, n) >= least.width && scaled(frame.height, n) >= least.height) {
            return n;
        }
    }
    return 8;
}

const char* JpegDecoder::error() const noexcept {
    return state_->message;
}

bool JpegDecoder::decode(const std::uint8_t* data, std::size_t size) noexcept {
    JpegState& state = *state_;
    jpeg_decompress_struct& info = state.info;
    state.truncated = false;
    state.message[0] = '\0';
    if (setjmp(state.jump) != 0) {
        jpeg_abort_decompress(&info);
        return false;
    }
    jpeg_mem_src(&info, data, static_cast<unsigned long>(size));
    if (jpeg_read_header(&info, TRUE) != JPEG_HEADER_OK) {
        std::snprintf(state.message, sizeof state.message, "no JPEG image in the frame");
        jpeg_abort_decompress(&info);
        return false;
    }
    const int eighths = scale_for(
        {static_cast<int>(info.image_width), static_cast<int>(info.image_height)}, least_);
    info.scale_num = static_cast<unsigned int>(eighths);
    info.scale_denom = 8;
    info.out_color_space = JCS_EXT_BGR;  // libjpeg-turbo: OpenCV's byte order, no swap after
    jpeg_calc_output_dimensions(&info);
    try {
        // Reallocates only when the size changes: the camera's mode is fixed while streaming.
        bgr_.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width),
                    CV_8UC3);
    } catch (const std::exception&) {
        std::snprintf(state.message, sizeof state.message, "out of memory for the frame");
        jpeg_abort_decompress(&info);
        return false;
    }
    jpeg_start_decompress(&info);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = bgr_.ptr(static_cast<int>(info.output_scanline));
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    scale_eighths_ = eighths;
    if (state.truncated) {
        std::snprintf(state.message, sizeof state.message, "the JPEG data ends early");
        return false;
    }
    return true;
}

}  // namespace raypoint::daemon
