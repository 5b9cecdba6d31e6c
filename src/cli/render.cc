// Copyright contactlaws authors.
//
// contactlaws render SCENE --output FILE.mp4 | FILE.gif | DIR/: the run drawn
// offscreen by MuJoCo's renderer, one frame at each simulated time
// k / (fps * slowmo), k = 0, 1, ... up to the duration: Advance's sample
// grid, so the frames are the states run's trajectory rows would hold (a
// fixed step samples at the first step within half a step of the frame
// time; the auto step is cut at the frame times). With the tracking camera
// (the default) the run is simulated twice: a first pass at the frame times
// finds what to frame (render/tracking_camera.h).

#include <signal.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/arena.h"
#include "cli/commands.h"
#include "cli/programs.h"
#include "cli/report.h"
#include "contactlaws/contact_model.h"
#include "render/frame_renderer.h"
#include "render/frame_sink.h"
#include "render/scene_look.h"
#include "render/tracking_camera.h"
#include "scene/number.h"
#include "sim/start_contact.h"
#include "sim/timestep_advice.h"

namespace contactlaws::cli {
namespace {

// Frames of at least this size, at most this: MuJoCo's overlay needs room,
// and a frame beyond 8192 is beyond what Mesa's llvmpipe renders.
constexpr long kMinPixels = 16;
constexpr long kMaxPixels = 8192;
// Frames in one video: an hour at 30 fps is 108000; more is a slow motion
// or a duration mistyped, refused before a run that would take days.
constexpr double kMaxFrames = 100000;

int ParsePixels(std::string_view option, const std::string& text) {
  const std::optional<long> pixels = ParseWholeNumber(text, kMinPixels, kMaxPixels);
  if (!pixels) {
    Refuse(option, text,
           fmt::format("must be a whole number in [{}, {}] (pixels)", kMinPixels, kMaxPixels));
  }
  return static_cast<int>(*pixels);
}

struct RenderPlan {
  CommonOptions common;
  render::OutputFormat format = render::OutputFormat::kMp4;
  render::FrameOptions frame;
  double fps = 0;
  double slowmo = 0;
};

RenderPlan Plan(const RenderArgs& args) {
  RenderPlan plan;
  plan.common = ParseCommon(args);
  ParseLawOverrides(args.law, args.restitution, &plan.common.simulation.overrides);
  plan.fps = ParsePositive("--fps", args.fps, "frames per second of video");
  plan.slowmo = ParsePositive("--slowmo", args.slowmo, "video seconds per simulated second");
  plan.frame.width = ParsePixels("--width", args.width);
  plan.frame.height = ParsePixels("--height", args.height);
  plan.frame.camera = args.camera.value_or(render::FrameOptions::kTrack);
  plan.frame.slowmo = plan.slowmo;
  if (args.force_scale) plan.frame.force_scale = ParsePositive("--force-scale", *args.force_scale, "m/N");
  // one frame at each k / (fps slowmo) up to the duration, t = 0 included
  const double frames = std::floor(plan.common.duration * plan.fps * plan.slowmo) + 1;
  if (frames > kMaxFrames) {
    throw Error(fmt::format("--duration={} at --fps={} and --slowmo={} is {:.0f} frames, more "
                            "than {:.0f}: shorten the run or lower --fps or --slowmo",
                            args.duration, args.fps, args.slowmo, frames, kMaxFrames));
  }
  plan.format = render::OutputFormatOf(args.output);
  render::RequireOutputFolder(plan.format, args.output);
  if (plan.format == render::OutputFormat::kMp4) {
    // H.264 in yuv420p halves the chroma both ways
    if (plan.frame.width % 2) Refuse("--width", args.width, "must be even for .mp4 (yuv420p)");
    if (plan.frame.height % 2) Refuse("--height", args.height, "must be even for .mp4 (yuv420p)");
  }
  return plan;
}

}  // namespace

int RenderCommand(const RenderArgs& args) {
  const RenderPlan plan = Plan(args);
  const std::string ffmpeg = plan.format == render::OutputFormat::kPngDirectory
                                 ? ""
                                 : RequireProgram("render --output " + args.output, "ffmpeg",
                                                  "ffmpeg");
  UniqueModel model = app::LoadSizedModel(args.scene, plan.common.simulation.overrides);
  if (plan.frame.named()) render::FindCamera(model.get(), args.scene, plan.frame.camera);
  const render::LookPlan look = args.plain ? render::LookPlan{} : render::PlanLook(model.get());
  if (!look.empty()) model = render::Dressed(model.get(), args.scene, look);
  render::FrameRenderer::Prepare(model.get(), plan.frame);
  const Scene scene(args.scene, std::move(model));
  std::unique_ptr<Simulation> sim = scene.Make(plan.common.simulation);
  if (!look.empty()) {
    fmt::print("{}: drawn with what it lacks of MuJoCo's samples' look: {} (--plain: MuJoCo's "
               "defaults)\n", scene.path(), look.Describe());
  }
  ReportSettle(*sim);
  const std::vector<StartContact> starts = StartContacts(sim.get());
  for (const std::string& w : DeepStartWarnings(*sim, starts, kCommandLineSpelling)) Warn(scene.path(), w);
  const std::vector<TimestepAdvice> advice = AdviseTimestep(sim.get(), starts);
  if (!plan.common.auto_timestep) {
    for (const std::string& w : TimestepWarnings(*sim, advice, kCommandLineSpelling)) Warn(scene.path(), w);
  }

  AdvanceOptions advance;
  advance.duration = plan.common.duration;
  advance.sample_rate = plan.fps * plan.slowmo;
  advance.auto_timestep = plan.common.auto_timestep;
  advance.steps_end_at_rows = true;  // each frame draws the data at its time
  advance.stop = &stop_signal;
  const auto start = std::chrono::steady_clock::now();
  // the tracking camera's first pass over the run, on a simulation of its own
  render::TrackedRun tracked;
  if (plan.frame.tracks()) {
    AdvanceResult first;
    tracked = render::TrackRun(scene.Make(plan.common.simulation).get(), advance, &first);
    if (first.status == AdvanceResult::Status::kInterrupted) {
      fmt::print(stderr, "contactlaws: interrupted in the tracking camera's first pass: no "
                         "file written\n");
      return kExitInterrupted;
    }
  }
  const std::chrono::duration<double> tracking = std::chrono::steady_clock::now() - start;

  signal(SIGPIPE, SIG_IGN);  // an ffmpeg that stops is an error of fwrite, not a signal
  std::unique_ptr<render::FrameSink> sink = render::MakeFrameSink(
      plan.format, args.output, ffmpeg, plan.frame.width, plan.frame.height, plan.fps);
  render::FrameRenderer renderer(*sim, plan.frame, tracked);
  std::vector<unsigned char> rgb;
  long frames = 0;
  std::chrono::duration<double> drawing{0};
  const AdvanceResult result = Advance(sim.get(), advance, [&](const std::vector<double>&) {
    const auto before = std::chrono::steady_clock::now();
    renderer.Draw(sim.get(), &rgb);
    drawing += std::chrono::steady_clock::now() - before;
    sink->Write(rgb);
    ++frames;
  });
  const std::chrono::duration<double> total = std::chrono::steady_clock::now() - start;
  if (result.status == AdvanceResult::Status::kInterrupted) {
    fmt::print(stderr, "contactlaws: interrupted at t = {:.6g} s: no file written\n", sim->time());
    return kExitInterrupted;
  }
  for (const std::string& w : RunWarnings(*sim, result)) Warn(scene.path(), w);
  sink->Commit();  // what was drawn until a divergence is valid, and written
  fmt::print("{}: {} frames of {}x{} at {} fps, {}x slow motion: {:.1f} ms per frame drawn, "
             "{:.2f} s in all{}\n", args.output, frames, plan.frame.width, plan.frame.height,
             plan.fps, plan.slowmo, frames ? 1e3 * drawing.count() / frames : 0.0, total.count(),
             plan.frame.tracks()
                 ? fmt::format(" ({:.2f} s of it the tracking camera's first pass)",
                               tracking.count())
                 : "");
  if (result.divergence) {
    fmt::print(stderr, "contactlaws: {}: run stopped: diverged at {}\n", scene.path(),
               DivergenceMessage(*sim, *result.divergence, advice, kCommandLineSpelling));
    return kExitIncomplete;
  }
  return 0;
}

}  // namespace contactlaws::cli
