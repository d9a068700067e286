// SPDX-License-Identifier: MIT
#include "jpeg_encoder.hpp"

// libjpeg's header needs size_t and FILE declared first.
#include <cstdio>
// clang-format off
#include <jpeglib.h>
// clang-format on

#include <csetjmp>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace raypoint::daemon {
namespace {

struct EncoderErrors {
    jpeg_error_mgr manager{};
    std::jmp_buf jump{};
    char message[JMSG_LENGTH_MAX] = {};
};

[[noreturn]] void on_error(j_common_ptr info) {
    auto* errors = reinterpret_cast<EncoderErrors*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->jump, 1);
}

}  // namespace

void encode_jpeg(const cv::Mat& bgr, int quality, std::vector<std::uint8_t>& out) {
    if (bgr.type() != CV_8UC3 || bgr.empty()) {
        throw std::invalid_argument("encode_jpeg: needs a non-empty CV_8UC3 image");
    }
    jpeg_compress_struct info{};
    EncoderErrors errors;
    info.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = on_error;
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    // Nothing with a destructor is created between setjmp and the libjpeg calls that may jump.
    if (setjmp(errors.jump) != 0) {
        jpeg_destroy_compress(&info);
        std::free(buffer);
        throw std::runtime_error(std::string("libjpeg compress: ") + errors.message);
    }
    jpeg_create_compress(&info);
    jpeg_mem_dest(&info, &buffer, &size);
    info.image_width = static_cast<JDIMENSION>(bgr.cols);
    info.image_height = static_cast<JDIMENSION>(bgr.rows);
    info.input_components = 3;
    info.in_color_space = JCS_EXT_BGR;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, quality, TRUE);
    // 4:2:2: luma 2x1, each chroma 1x1.
    info.comp_info[0].h_samp_factor = 2;
    info.comp_info[0].v_samp_factor = 1;
    jpeg_start_compress(&info, TRUE);
    while (info.next_scanline < info.image_height) {
        JSAMPROW row =
            const_cast<JSAMPROW>(bgr.ptr<std::uint8_t>(static_cast<int>(info.next_scanline)));
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    out.assign(buffer, buffer + size);
    jpeg_destroy_compress(&info);
    std::free(buffer);
}

}  // namespace raypoint::daemon
