// SPDX-License-Identifier: MIT
// INI syntax: what is accepted (comments, whitespace, CRLF, BOM, inline comments), and every
// kind of wrong line answered with its exact "file:line:" message, all of them, in line order.

#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "ini_testing.hpp"

namespace raypoint::config {
namespace {

using testing::formatted;
using testing::load_text;
using Errors = std::vector<std::string>;

TEST(IniSyntax, EmptyAndCommentOnlyFilesAreTheDefaults) {
    for (const char* text : {"", "\n\n", "; one\n# two\n   ; three\n\t# four", "\r\n"}) {
        const auto loaded = load_text(text);
        EXPECT_EQ(loaded.errors, Errors{}) << text;
        EXPECT_TRUE(loaded.file.settings.empty()) << text;
        EXPECT_FALSE(loaded.file.preset) << text;
        EXPECT_EQ(formatted(loaded.config), formatted(Config{})) << text;
    }
}

TEST(IniSyntax, WhitespaceAroundEverythingIsTrimmed) {
    const auto loaded = load_text("  [ estimator ]  \n\t rays\t=\t 8 \t\nmethod=ray\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
    EXPECT_EQ(loaded.config.core.estimator.kind, core::EstimatorKind::ray);
    ASSERT_EQ(loaded.file.settings.size(), 2U);
    EXPECT_EQ(std::get<int>(loaded.file.settings[0].value), 8);
    EXPECT_EQ(loaded.file.settings[0].line, 2);
}

TEST(IniSyntax, IndentedKeysAreKeysNotContinuations) {
    // inih alone would append "recasts = 3" to the value of rays (Python's multi-line values).
    const auto loaded = load_text("[estimator]\nrays = 8\n    recasts = 3\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
    EXPECT_EQ(loaded.config.core.estimator.recasts, 3);
}

TEST(IniSyntax, CrlfLineEndings) {
    const auto loaded = load_text("[estimator]\r\nrays = 8\r\nmethod = ray\r\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
    EXPECT_EQ(loaded.config.core.estimator.kind, core::EstimatorKind::ray);
    EXPECT_EQ(load_text("[estimator]\r\n\r\nrays = 2\r\n").errors,
              Errors{"t.ini:3: [estimator] rays: value out of range (allowed: 3..256)"});
}

TEST(IniSyntax, Utf8BomAtTheStartOnly) {
    const auto loaded = load_text("\xEF\xBB\xBF[estimator]\nrays = 8\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
    EXPECT_EQ(load_text("\xEF\xBB\xBF; comment\n").errors, Errors{});
    EXPECT_EQ(load_text("\n\xEF\xBB\xBF[estimator]\n").errors,
              Errors{"t.ini:2: expected \"key = value\", \"[section]\" or a comment, got "
                     "\"\xEF\xBB\xBF[estimator]\""});
}

TEST(IniSyntax, CommentsAfterValuesAndHeaders) {
    const auto loaded = load_text(
        "[estimator] ; the estimator\nrays = 8 ; eight\nrecasts = 3\t# three\n"
        "[tracking] # tracking\nmin_area = 0.05 ;; twice\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
    EXPECT_EQ(loaded.config.core.estimator.recasts, 3);
    EXPECT_EQ(loaded.config.core.tracking.min_area, 0.05);
    // Without whitespace before it, ';' or '#' is part of the value.
    EXPECT_EQ(load_text("[estimator]\nmethod = ray;x\n").errors,
              Errors{"t.ini:2: [estimator] method: unknown value, did you mean ray? (allowed: "
                     "ray|iterative-ray|iterative-ny-ray|raster)"});
    EXPECT_EQ(load_text("[estimator]\nrays = 8#x\n").errors,
              Errors{"t.ini:2: [estimator] rays: not an integer (allowed: 3..256)"});
}

TEST(IniSyntax, ColonSeparatesLikeEquals) {
    const auto loaded = load_text("[estimator]\nrays: 8\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(loaded.config.core.estimator.rays, 8);
}

TEST(IniSyntax, MalformedLinesAreReportedAndTheRestStillRead) {
    const auto loaded = load_text("[estimator]\nrays 8\nrecasts = 3\n= 5\n[tracking]\nmin_area");
    EXPECT_EQ(loaded.errors,
              (Errors{"t.ini:2: expected \"key = value\", \"[section]\" or a comment, got "
                      "\"rays 8\"",
                      "t.ini:4: missing key name: \"= 5\"",
                      "t.ini:6: expected \"key = value\", \"[section]\" or a comment, got "
                      "\"min_area\""}));
    EXPECT_EQ(loaded.config.core.estimator.recasts, 3);
}

TEST(IniSyntax, BadSectionHeaders) {
    EXPECT_EQ(load_text("[estimator\nrays = 8\n[tracking]\nmin_area = 0.05\n").errors,
              Errors{"t.ini:1: unterminated section header \"[estimator\" (no \"]\")"});
    // The keys under it are skipped: nothing would tell which section they were meant for.
    EXPECT_TRUE(load_text("[estimator\nrays = 8\n").file.settings.empty());
    EXPECT_EQ(load_text("[estimator] rays = 8\n").errors,
              Errors{"t.ini:1: [estimator]: text after the section header: \"rays = 8\""});
}

TEST(IniSyntax, UnknownSectionsSuggestTheNearest) {
    const auto loaded = load_text("[trackng]\nmin_area = 0.05\nbogus = 1\n[genral]\npreset = x\n");
    EXPECT_EQ(loaded.errors,
              (Errors{"t.ini:1: [trackng]: unknown section (did you mean [tracking]?)",
                      "t.ini:4: [genral]: unknown section (did you mean [general]?)"}));
    EXPECT_TRUE(loaded.file.settings.empty());
}

TEST(IniSyntax, UnknownKeysSuggestTheNearest) {
    EXPECT_EQ(load_text("[tracking]\nmin_aera = 0.05\n").errors,
              Errors{"t.ini:2: [tracking] min_aera: unknown key (did you mean min_area?)"});
    EXPECT_EQ(load_text("[estimator]\nmin_area = 0.05\n").errors,
              Errors{"t.ini:2: [estimator] min_area: unknown key (did you mean [tracking] "
                     "min_area?)"});
    // A typo in the right section beats an equally near name in another one.
    EXPECT_EQ(load_text("[tracking]\nidge_threshold = 9\n").errors,
              Errors{"t.ini:2: [tracking] idge_threshold: unknown key (did you mean "
                     "idle_threshold?)"});
    EXPECT_EQ(load_text("[tracking]\nedge_threshold = 9\n").errors,
              Errors{"t.ini:2: [tracking] edge_threshold: unknown key (did you mean [preprocess] "
                     "edge_threshold?)"});
    EXPECT_EQ(load_text("rays = 8\n").errors,
              Errors{"t.ini:1: rays: key before the first [section] (did you mean [estimator] "
                     "rays?)"});
    EXPECT_EQ(load_text("preset = paper\n").errors,
              Errors{"t.ini:1: preset: key before the first [section] (did you mean [general] "
                     "preset?)"});
    EXPECT_EQ(load_text("[general]\npresets = paper\n").errors,
              Errors{"t.ini:2: [general] presets: unknown key (did you mean preset?)"});
    EXPECT_EQ(load_text("[general]\nrays = 8\n").errors,
              Errors{"t.ini:2: [general] rays: unknown key (did you mean [estimator] rays?)"});
    EXPECT_EQ(load_text("[tracking]\nMin_Area = 0.05\n").errors,
              Errors{"t.ini:2: [tracking] Min_Area: unknown key (did you mean min_area?)"});
}

TEST(IniSyntax, GarbageGetsNoSuggestion) {
    // Nothing is near: a suggestion would be nonsense.
    EXPECT_EQ(load_text("[tracking]\nxqzwvjkpf = 1\n").errors,
              Errors{"t.ini:2: [tracking] xqzwvjkpf: unknown key (raypoint print-config lists "
                     "every key)"});
    EXPECT_EQ(load_text("[qqqqqqqqq]\n").errors,
              Errors{"t.ini:1: [qqqqqqqqq]: unknown section (raypoint print-config lists every "
                     "section)"});
}

TEST(IniSyntax, ChoicesInAnyCaseAndTheNearestForAWrongOne) {
    const auto loaded = load_text("[pointer]\nmode = Absolute\n[estimator]\nmethod = RASTER\n");
    EXPECT_EQ(loaded.errors, Errors{});
    EXPECT_EQ(load_text("[pointer]\nmode = absolut\n").errors,
              Errors{"t.ini:2: [pointer] mode: unknown value, did you mean absolute? (allowed: "
                     "relative|absolute)"});
    EXPECT_EQ(load_text("[pointer]\nmode = zzzzzzzz\n").errors,
              Errors{"t.ini:2: [pointer] mode: unknown value (allowed: relative|absolute)"});
}

TEST(IniSyntax, DuplicateKeysNameBothLines) {
    const auto loaded =
        load_text("[estimator]\nrays = 8\n[tracking]\nmin_area = 0.05\n[estimator]\nrays = 9\n");
    EXPECT_EQ(loaded.errors, Errors{"t.ini:6: [estimator] rays: duplicate key (first on line 2)"});
    EXPECT_EQ(load_text("[general]\npreset = paper\npreset = default\n").errors,
              Errors{"t.ini:3: [general] preset: duplicate key (first on line 2)"});
    // A section may come back; only a key may not.
    EXPECT_EQ(load_text("[estimator]\nrays = 8\n[tracking]\n[estimator]\nrecasts = 3\n").errors,
              Errors{});
}

TEST(IniSyntax, PresetIsAppliedBeforeTheFileWhereverItStands) {
    const auto paper = load_text("[estimator]\nrays = 8\n[general]\npreset = paper\n");
    EXPECT_EQ(paper.errors, Errors{});
    EXPECT_EQ(paper.file.preset, "paper");
    EXPECT_EQ(paper.config.core.estimator.rays, 8);
    EXPECT_EQ(paper.config.core.preprocess.edge_threshold, 128);  // the paper's
    EXPECT_EQ(load_text("[general]\npreset = papr\n").errors,
              Errors{"t.ini:2: [general] preset: unknown preset (allowed: default|paper)"});
    // The caller's preset (the command line's --preset) wins over the file's.
    const auto overridden = load_text("[general]\npreset = paper\n", "default");
    EXPECT_EQ(overridden.config.core.preprocess.edge_threshold, 96);
}

TEST(IniSyntax, EveryErrorInLineOrder) {
    const auto loaded = load_text(
        "[estimator]\nrays = 1\nrays = 9\nrayz = 1\n[tracking\nmin_area=0.05\n[output]\n"
        "ema_weight = 2\nsmoothing\n");
    EXPECT_EQ(loaded.errors,
              (Errors{"t.ini:2: [estimator] rays: value out of range (allowed: 3..256)",
                      "t.ini:3: [estimator] rays: duplicate key (first on line 2)",
                      "t.ini:4: [estimator] rayz: unknown key (did you mean rays?)",
                      "t.ini:5: unterminated section header \"[tracking\" (no \"]\")",
                      "t.ini:8: [output] ema_weight: value out of range (allowed: 0..0.999)",
                      "t.ini:9: expected \"key = value\", \"[section]\" or a comment, got "
                      "\"smoothing\""}));
    EXPECT_TRUE(loaded.file.settings.empty());
}

TEST(IniSyntax, NulBytesAndOverlongLines) {
    EXPECT_EQ(load_text(std::string("[estimator]\nra\0ys = 8\n", 22)).errors,
              Errors{"t.ini:2: contains a NUL byte (not a text file?)"});
    const auto long_setting = load_text("[estimator]\nrays = " + std::string(300, '8') + "\n");
    ASSERT_EQ(long_setting.errors.size(), 1U);
    EXPECT_EQ(long_setting.errors[0].rfind("t.ini:2: line too long (a setting has at most ", 0), 0U)
        << long_setting.errors[0];
    // Comments and blank lines may be any length, and the next line keeps its number.
    const auto long_comment = load_text("# " + std::string(100000, 'c') + "\n" +
                                        std::string(5000, ' ') + "\n[estimator]\nrays = 2\n");
    EXPECT_EQ(long_comment.errors,
              Errors{"t.ini:4: [estimator] rays: value out of range (allowed: 3..256)"});
}

TEST(IniSyntax, LongBadLinesAreShortenedInTheMessage) {
    const std::string word(100, 'x');
    EXPECT_EQ(load_text("[estimator]\n" + word + "\n").errors,
              Errors{"t.ini:2: expected \"key = value\", \"[section]\" or a comment, got \"" +
                     std::string(60, 'x') + "...\""});
}

}  // namespace
}  // namespace raypoint::config
