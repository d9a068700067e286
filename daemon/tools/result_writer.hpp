// SPDX-License-Identifier: MIT
#pragma once
// One line a frame on stdout: JSONL (the schema the scoring method reads, docs/scoring.md) or CSV.

#include <cstdio>

#include "raypoint/core/tracker.hpp"

namespace raypoint::daemon {

enum class OutputFormat { jsonl, csv };

class ResultWriter {
  public:
    ResultWriter(std::FILE* out, OutputFormat format);
    // `microseconds`: time the core spent on the frame, decode excluded.
    void write(const core::FrameResult& result, long microseconds);

  private:
    std::FILE* out_;
    OutputFormat format_;
};

}  // namespace raypoint::daemon
