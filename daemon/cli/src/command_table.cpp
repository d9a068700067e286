// SPDX-License-Identifier: MIT
#include "command_table.hpp"

#include <algorithm>
#include <array>

#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::daemon {
namespace {

constexpr std::array run_options{
    OptionSpec{"--camera", "DEVICE", "/dev/videoN, /dev/v4l/by-id/..., or auto (default)"},
    OptionSpec{"--lock-exposure", "", "lock auto exposure, gain and white balance"},
    OptionSpec{"--input", "FILE", "a recorded video instead of the camera, at its own pace"},
    OptionSpec{"--unpaced", "", "with --input: as fast as the core runs"},
    OptionSpec{"--realtime", "",
               "with --input: decode the clip first, then replay it from\n"
               "memory as a YUYV camera would deliver it (the daemon's\n"
               "own cost, printed at exit and in ctl status)"},
    OptionSpec{"--realtime-format", "yuyv|mjpeg",
               "with --realtime: the replayed camera's frames: yuyv\n"
               "(default) or mjpeg (quality 85, decoded when due, as the\n"
               "camera path decodes an MJPEG camera's)"},
    OptionSpec{"--duration", "SECONDS", "stop after SECONDS (with --realtime the clip loops)"},
    OptionSpec{"--sink", "SPEC", "uinput (default), file:PATH (the events as text), null"},
    OptionSpec{"--control", "PATH", "control socket (default $XDG_RUNTIME_DIR/raypoint.sock)"},
    OptionSpec{"--no-control", "", "no control socket"},
};
constexpr std::array ctl_options{
    OptionSpec{"--control", "PATH", "control socket (default $XDG_RUNTIME_DIR/raypoint.sock)"},
    OptionSpec{"--json", "", "status as one JSON object (numbers, true/false, strings)"},
};
constexpr std::array track_options{
    OptionSpec{"--format", "jsonl|csv", "output format (default jsonl)"},
    OptionSpec{"--annotate", "OUT.mp4", "also write the video with what the tracker saw"},
    OptionSpec{"--fps", "N",
               "frame rate for the timestamps (default: the\n"
               "container's; 30 for an image sequence)"},
    OptionSpec{"--verbose", "", "say on stderr when and why a target is lost or recovered"},
    OptionSpec{"--plot", "OUT.png", "also plot x, y, z, the state and the clicks over time"},
};
constexpr std::array plot_options{
    OptionSpec{"--output", "OUT.png", "the picture to write (also -o OUT.png)"},
    OptionSpec{"--events", "FILE", "clicks from a file sink's events (run --sink file:FILE)"},
};
// preview: where the frames come from, and the headless mode the tests drive.
constexpr std::array preview_options{
    OptionSpec{"--camera", "DEVICE", "/dev/videoN, /dev/v4l/by-id/..., or auto (default)"},
    OptionSpec{"--input", "CLIP", "a recorded video instead of the camera"},
    OptionSpec{"--headless", "", "no window; with --frames N and --screenshot OUT.png"},
    OptionSpec{"--frames", "N", "headless: stop after N frames"},
    OptionSpec{"--screenshot", "OUT.png", "headless: write the last view"},
    OptionSpec{"--view", "edges|difference", "what is drawn under the markers (key v)"},
    OptionSpec{"--control", "PATH", "the daemon's control socket, paused while on camera"},
    OptionSpec{"--no-control", "", "do not pause a running daemon"},
};
// setup: preview's, and the screen the gain is proposed for.
constexpr auto setup_options = [] {
    std::array<OptionSpec, preview_options.size() + 1> options{};
    std::copy(preview_options.begin(), preview_options.end(), options.begin());
    options.back() =
        OptionSpec{"--screen-width", "PIXELS", "the screen the pointer moves on (for the gain)"};
    return options;
}();
constexpr std::array demo_options{
    OptionSpec{"--scene", "NAME", "scene preset (default nonconvex)"},
    OptionSpec{"--annotate", "OUT.mp4", "annotated clip (default raypoint-demo.mp4)"},
};
constexpr std::array compare_options{
    OptionSpec{"--out", "FILE", "write the Markdown report to FILE (default: stdout)"},
};
constexpr std::array bench_options{
    OptionSpec{"--peers", "LIST", "camshift,kcf,csrt,mil (default all) or none"},
    OptionSpec{"--scenes", "LIST",
               "rendered scenes without CLIP (default ideal,lowlight,\n"
               "interfering,nonconvex,realworld,fast,pause)"},
    OptionSpec{"--frames", "N", "at most N frames a clip"},
    OptionSpec{"--format", "table|markdown|jsonl", "output format (default table)"},
};
constexpr std::array eval_clicks_options{
    OptionSpec{"--set-name", "full|ci|none", "the gesture set (default full)"},
    OptionSpec{"--seed", "N", "the set's seed (default 1)"},
    OptionSpec{"--backgrounds", "DIR", "the set in front of the JPEG and PNG photographs in DIR"},
    OptionSpec{"--jobs", "N", "clips tracked at once (default 1)"},
    OptionSpec{"--sweep", "", "also sweep the click settings (a table)"},
    OptionSpec{"--plot", "OUT.png", "the sweep, plotted"},
    OptionSpec{"--cache", "DIR", "keep the tracker's results of rendered clips there"},
    OptionSpec{"--misses", "", "say on stderr why each miss and false click happened"},
    OptionSpec{"--trace", "CLIP", "each frame of the clip named CLIP on stderr"},
    OptionSpec{"--write", "DIR",
               "write the set as videos with their truth, and stop (with --trace, that clip only)"},
    OptionSpec{"--min-recall", "F", "exit 1 when fewer target pushes press"},
    OptionSpec{"--max-false-per-minute", "F", "exit 1 with more false clicks a minute"},
    OptionSpec{"--max-latency-ms", "F", "exit 1 with a longer median latency (target pushes)"},
    OptionSpec{"--max-offset-px", "F", "exit 1 with a larger median offset"},
    OptionSpec{"--min-gesture-recall", "F",
               "exit 1 when a right click, double click or scroll is recognised less"},
    OptionSpec{"--max-confusion", "F",
               "exit 1 when more of a gesture is taken for a left click, or the reverse"},
};
constexpr std::array print_config_options{
    OptionSpec{"--defaults", "", "read no configuration file"},
};
constexpr std::array settings_options{
    OptionSpec{"--config", "FILE", "read the settings from an INI file (see print-config)"},
    OptionSpec{"--preset", "default|paper",
               "start from the measured defaults or the paper exactly"},
    OptionSpec{"--estimator", "NAME", "ray|iterative-ray|iterative-ny-ray|raster"},
    OptionSpec{"--set", "section.key=value", "change one setting (repeatable; see print-config)"},
};
constexpr std::array help_options{
    OptionSpec{"--help", "", "this help, then exit (also -h)"},
};

// One row a command, in the order `raypoint --help` lists them.
constexpr std::array commands{
    CommandSpec{"run", "",
                "the daemon: webcam in, a virtual pointer out (a systemd user\n"
                "service: systemctl --user enable --now raypoint). SIGHUP\n"
                "reloads the configuration; SIGINT and SIGTERM stop it,\n"
                "releasing every button.",
                run_options, true},
    CommandSpec{"ctl", "pause|resume|toggle|recenter|status",
                "talk to the running daemon over its control socket; pause\n"
                "closes the camera, resume opens it again, toggle does\n"
                "whichever applies (for a desktop shortcut)",
                ctl_options},
    CommandSpec{"doctor",
                "",
                "check the configuration, the webcam, /dev/uinput and the\n"
                "service, and print the fix for each failure",
                {}},
    CommandSpec{"track", "INPUT",
                "track a recorded video or image sequence (\"frames/%04d.png\"),\n"
                "one line a frame on stdout",
                track_options, true},
    CommandSpec{"plot", "TRACK.jsonl",
                "plot track's output: x, y, z, the state band and the clicks\n"
                "over time, as a PNG",
                plot_options},
    CommandSpec{"preview", "",
                "a window with the camera and what the tracker sees, trackbars\n"
                "for the most-tuned settings; keys: v edges/difference, space\n"
                "pause, w write them into the INI file, q quit. Pauses a running\n"
                "daemon (ctl pause) while it has the camera",
                preview_options, true},
    CommandSpec{"setup", "",
                "guided first run: measures hand size, motion range and push\n"
                "depth, proposes [pointer] gain, the active region and [click]\n"
                "press_rise/release_rise, lets you try them, writes the INI on\n"
                "yes (--headless: when the try-it clicks once a push)",
                setup_options, true},
    CommandSpec{"demo", "",
                "render a scene in memory, track it, print the 3D positions and\n"
                "write an annotated clip",
                demo_options, true},
    CommandSpec{"compare-estimators", "", "measure the four estimators (docs/estimators.md)",
                compare_options, true},
    CommandSpec{"bench", "[CLIP...]",
                "time raypoint's core (each estimator) against OpenCV's CamShift,\n"
                "KCF, CSRT and MIL on the same decoded frames, with accuracy\n"
                "where a CLIP has truth.jsonl and masks.npz beside it; a CLIP is\n"
                "a video or a scene folder (default: rendered scenes)",
                bench_options, true},
    CommandSpec{"eval-clicks", "[CLIP...]",
                "click by depth on the rendered gesture set and on recorded\n"
                "CLIPs (truth in CLIP.clicks): recall, false clicks, latency\n"
                "and offset, per condition (docs/clicks.md)",
                eval_clicks_options, true},
    CommandSpec{"print-config", "",
                "print the effective configuration as an INI file (the file\n"
                "raypoint run reads, see check-config, and the options below)",
                print_config_options, true},
    CommandSpec{"check-config",
                "[FILE]",
                "check a configuration file, or the one raypoint run reads\n"
                "($XDG_CONFIG_HOME/raypoint/raypoint.ini, then\n"
                "raypoint/raypoint.ini in $XDG_CONFIG_DIRS)",
                {}},
};

// Prints `text`'s lines, the first after `head` padded to `column`, the others indented to it.
void print_block(std::FILE* out, std::string_view head, std::string_view text, std::size_t column) {
    std::fwrite(head.data(), 1, head.size(), out);
    std::size_t used = head.size();
    if (used + 1 > column) {
        std::fputs("\n", out);
        used = 0;
    }
    bool first = true;
    while (true) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        std::fprintf(out, "%*s%.*s\n", static_cast<int>(column - (first ? used : 0)), "",
                     static_cast<int>(line.size()), line.data());
        first = false;
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
}

std::string option_head(const OptionSpec& option) {
    return std::string(option.name) + (option.value.empty() ? "" : " ") + std::string(option.value);
}

void print_options(std::FILE* out, std::span<const OptionSpec> options, std::size_t indent) {
    for (const OptionSpec& option : options)
        print_block(out, std::string(indent, ' ') + option_head(option), option.help, 29);
}

// Every option `command` accepts: its own, --help, and the settings options when it takes them.
std::vector<const OptionSpec*> accepted_options(const CommandSpec& command) {
    std::vector<const OptionSpec*> accepted;
    for (const auto list : {command.options, std::span<const OptionSpec>(help_options),
                            command.settings ? std::span<const OptionSpec>(settings_options)
                                             : std::span<const OptionSpec>()}) {
        for (const OptionSpec& option : list)
            accepted.push_back(&option);
    }
    return accepted;
}

}  // namespace

std::span<const CommandSpec> command_table() {
    return commands;
}

const CommandSpec* find_command(std::string_view name) {
    for (const CommandSpec& command : commands)
        if (command.name == name) return &command;
    return nullptr;
}

void print_usage(std::FILE* out) {
    std::fputs(
        "usage: raypoint COMMAND [options]\n"
        "       raypoint COMMAND --help      raypoint --version\n\ncommands:\n",
        out);
    std::string with_settings;
    for (const CommandSpec& command : commands) {
        std::string head = "  " + std::string(command.name);
        if (!command.operands.empty()) head.append(" ").append(command.operands);
        print_block(out, head, command.summary, 19);
        print_options(out, command.options, 6);
        if (command.settings)
            with_settings += (with_settings.empty() ? "" : ", ") + std::string(command.name);
    }
    std::fprintf(out, "\noptions for %s:\n", with_settings.c_str());
    print_options(out, settings_options, 2);
    std::fputs(
        "\nExit status: 0 on success, 1 when an input, a device or the settings fail,\n"
        "2 for a wrong command line.\n",
        out);
}

void print_command_help(const CommandSpec& command, std::FILE* out) {
    std::fprintf(out, "usage: raypoint %.*s%s%.*s%s\n\n", static_cast<int>(command.name.size()),
                 command.name.data(), command.operands.empty() ? "" : " ",
                 static_cast<int>(command.operands.size()), command.operands.data(),
                 command.options.empty() && !command.settings ? "" : " [options]");
    std::fprintf(out, "%.*s\n\noptions:\n", static_cast<int>(command.summary.size()),
                 command.summary.data());
    print_options(out, command.options, 2);
    if (command.settings) print_options(out, settings_options, 2);
    print_options(out, help_options, 2);
}

std::string_view closest_name(std::string_view wanted,
                              std::span<const std::string_view> candidates) {
    std::string_view best;
    std::size_t best_distance = 0;
    for (const std::string_view candidate : candidates) {
        const std::size_t distance = config::edit_distance(wanted, candidate);
        if (best.empty() || distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    // A third of the letters wrong is a typo; more is another word.
    const std::size_t limit = std::min<std::size_t>(3, wanted.size() / 3);
    return best_distance <= limit ? best : std::string_view();
}

std::vector<std::string> normalize_options(const CommandSpec& command,
                                           std::span<const std::string_view> args) {
    std::vector<std::string> out;
    bool options_end = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (options_end || !arg.starts_with("--")) {
            out.emplace_back(arg);
            continue;
        }
        if (arg == "--") {
            options_end = true;
            continue;
        }
        const std::size_t equals = arg.find('=');
        const std::string_view name = arg.substr(0, equals);
        const OptionSpec* option = nullptr;
        std::vector<std::string_view> names;
        for (const OptionSpec* known : accepted_options(command)) {
            if (known->name == name) option = known;
            names.push_back(known->name);
        }
        if (option == nullptr) {
            const std::string_view near = closest_name(name, names);
            throw UsageError(std::string(name) + ": unknown option" +
                             (near.empty() ? "" : " (did you mean " + std::string(near) + "?)") +
                             "; see raypoint " + std::string(command.name) + " --help");
        }
        out.emplace_back(name);
        if (option->value.empty()) {
            if (equals != std::string_view::npos)
                throw UsageError(std::string(name) + ": takes no value");
        } else if (equals != std::string_view::npos) {
            out.emplace_back(arg.substr(equals + 1));
        } else if (i + 1 < args.size()) {
            out.emplace_back(args[++i]);
        } else {
            throw UsageError(std::string(name) + ": missing " + std::string(option->value));
        }
    }
    return out;
}

}  // namespace raypoint::daemon
