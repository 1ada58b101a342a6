// nanopush assemble: several bars from their observed poses into a pattern (docs/planning.md,
// "Assembly").
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/json.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/planning/assemble.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "scene_args.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

namespace fs = std::filesystem;

struct AssembleOptions {
  std::string objects, pattern, scene = "tip_push_nanorod", tolerance = "1e-9,0.01", objective = "pushes", out,
                                format = "png";
  std::vector<std::string> sets;
  int max_pushes = 10;
  double gap = 2e-9;
  bool quiet = false;
};

/// Poses from a CSV with the columns x, y, theta (m, m, rad; any order, '#' comments).
std::vector<plan::Pose> read_poses(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "(unreadable)", "a CSV of poses x, y, theta (m, m, rad)");
  csv::ReadOptions ro;
  ro.comments = true;
  csv::Reader reader(in, path, ro);
  csv::Record rec;
  if (!reader.next(rec)) throw InputError(path, "(empty)", "a header x,y,theta and one row per bar");
  int cx = -1, cy = -1, ct = -1;
  for (std::size_t i = 0; i < rec.fields.size(); ++i) {
    const std::string& h = rec.fields[i];
    int* slot = h == "x" ? &cx : h == "y" ? &cy : h == "theta" ? &ct : nullptr;
    if (!slot) throw InputError(path + ":" + std::to_string(rec.line), h, "unknown column: the columns are x, y, theta");
    if (*slot >= 0) throw InputError(path + ":" + std::to_string(rec.line), h, "column given twice");
    *slot = static_cast<int>(i);
  }
  if (cx < 0 || cy < 0 || ct < 0)
    throw InputError(path + ":" + std::to_string(rec.line), csv::join(rec.fields), "the header must name x, y and theta");
  std::vector<plan::Pose> poses;
  while (reader.next(rec)) {
    const std::string where = path + ":" + std::to_string(rec.line);
    if (rec.fields.size() != 3) throw InputError(where, csv::join(rec.fields), "three cells x, y, theta");
    const auto v = number_list(where, rec.fields[static_cast<std::size_t>(cx)] + "," + rec.fields[static_cast<std::size_t>(cy)] +
                                          "," + rec.fields[static_cast<std::size_t>(ct)],
                               3, "three finite numbers x, y, theta (m, m, rad)");
    poses.push_back({v[0], v[1], v[2]});
  }
  return poses;
}

void write_outputs(const Scene& sc, const std::vector<plan::Pose>& objects, const std::vector<plan::Pose>& slots,
                   const plan::AssemblyResult& r, const fs::path& dir) {
  fs::create_directories(dir);
  {
    CsvWriter w(dir / "assembly.csv",
                columns("assemble"),
                sc.name);
    w.run_info({{"status", to_string(r.status)}, {"assignment_cost_m", r.assignment_cost}, {"planning_seconds", r.planning_seconds}});
    for (const auto& m : r.moves) {
      int k = 1;
      for (const auto& p : m.plan.pushes)
        w.row({double(m.object + 1), double(m.slot + 1), double(k++), p.start_x, p.start_y, p.direction, p.speed,
               p.travel, p.end.x, p.end.y, p.end.theta});
    }
    w.commit();
  }
  auto pose = [](const plan::Pose& p) { return json{{"x", json_number(p.x)}, {"y", json_number(p.y)}, {"theta", json_number(p.theta)}}; };
  json bars = json::array();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const auto& slot = slots[static_cast<std::size_t>(r.slot_of[i])];
    const auto& end = r.final_poses[i];
    bars.push_back({{"bar", i + 1},
                    {"slot", r.slot_of[i] + 1},
                    {"start", pose(objects[i])},
                    {"goal", pose(slot)},
                    {"final", pose(end)},
                    {"final_distance_m", json_number(std::hypot(end.x - slot.x, end.y - slot.y))},
                    {"final_angle_rad", json_number(std::fabs(plan::angle_error(end.theta, slot.theta, true)))}});
  }
  json order = json::array();
  for (const auto& m : r.moves) order.push_back(m.object + 1);
  const json doc = {{"scene", sc.name}, {"status", to_string(r.status)}, {"message", r.message}, {"order", order},
                    {"assignment_cost_m", json_number(r.assignment_cost)},
                    {"planning_seconds", json_number(r.planning_seconds)}, {"bars", bars}};
  write_file_atomic(dir / "assembly.json", json_text(doc));
  {  // Outlines: each bar at its start (0) and its end (1), each slot (2); the tip paths.
    CsvWriter w(dir / "outlines.csv",
                columns("assemble_outlines"),
                sc.name);
    auto outline = [&](int kind, const plan::Pose& p) {
      const double a = sc.geometry.a, b = sc.geometry.b, c = std::cos(p.theta), s = std::sin(p.theta);
      const double ux[] = {-a, a, a, -a, -a}, uy[] = {-b, -b, b, b, -b};
      for (int j = 0; j < 5; ++j) w.row({double(kind), p.x + c * ux[j] - s * uy[j], p.y + s * ux[j] + c * uy[j]});
      w.blank_line();
    };
    for (const auto& p : objects) outline(0, p);
    for (const auto& p : r.final_poses) outline(1, p);
    for (const auto& p : slots) outline(2, p);
    w.commit();
    CsvWriter t(dir / "tip_path.csv",
                columns("assemble_tip_path"),
                sc.name);
    for (const auto& m : r.moves)
      for (const auto& p : m.plan.pushes) {
        t.row({double(m.object + 1), p.start_x, p.start_y, 1.0});
        t.row({double(m.object + 1), p.start_x + p.travel * std::cos(p.direction),
               p.start_y + p.travel * std::sin(p.direction), 0.0});
        t.blank_line();
      }
    t.commit();
  }
  const std::string body =
      "set size ratio -1\nset xlabel 'x (nm)'\nset ylabel 'y (nm)'\nset key outside right noenhanced\n"
      "set datafile separator ','\nset palette defined (0 'gray60', 1 'blue', 2 'red')\nunset colorbox\n"
      "plot '" + (dir / "outlines.csv").string() +
      "' skip 1 using ($2*1e9):($3*1e9):1 with lines lc palette lw 2 title 'bars at start (grey), at end (blue); slots (red)', \\\n"
      "     '" + (dir / "tip_path.csv").string() +
      "' skip 1 using ($2*1e9):($3*1e9) with linespoints lc rgb 'black' dt 2 pt 7 ps 0.5 title 'tip paths'\n";
  plot::render_script(body, dir / "assembly.png");
}

int assemble_cmd(const AssembleOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  set_provenance_scene(o.scene);
  plot::set_format(plot::parse_format(o.format));
  const auto tol = number_list("--tolerance", o.tolerance, 2, "two numbers D,A (m, rad)");
  plan::AssemblyOptions ao;
  ao.plan.tolerance_distance = tol[0];
  ao.plan.tolerance_angle = tol[1];
  ao.plan.objective = plan::parse_objective(o.objective);
  ao.plan.max_pushes = o.max_pushes;
  ao.gap = o.gap;
  const auto objects = read_poses(o.objects), slots = read_poses(o.pattern);
  const plan::AssemblyResult r = plan::assemble(sc, objects, slots, ao);
  const fs::path dir = o.out.empty() ? sc.name + ".assembly" : o.out;
  write_outputs(sc, objects, slots, r, dir);
  if (!o.quiet) {
    std::cerr << std::setprecision(6) << sc.name << ": " << to_string(r.status) << ", " << objects.size() << " bars, "
              << r.moves.size() << " moved, planning " << r.planning_seconds << " s\n";
    for (const auto& m : r.moves)
      std::cerr << "  bar " << m.object + 1 << " -> slot " << m.slot + 1 << ": " << m.plan.pushes.size() << " push(es), "
                << m.plan.final_distance << " m and " << m.plan.final_angle << " rad from the slot\n";
    std::cerr << "  pushes: " << (dir / "assembly.csv").string() << " (and assembly.json, tip_path.csv, "
              << plot::figure_path(dir / "assembly.png").filename().string() << ")\n";
    if (!r.assembled()) std::cerr << "nanopush: not_found: " << r.message << "\n";
  }
  return r.assembled() ? 0 : 3;
}

RegisterCommand reg_assemble{
    {"assemble", "Move several bars from their observed poses into a pattern, each bar's pushes planned and kept clear of "
                 "the others (docs/planning.md)", 76,
     [](CLI::App& app) -> std::function<int()> {
       auto o = std::make_shared<AssembleOptions>();
       app.add_option("OBJECTS", o->objects, "CSV of the bars' observed poses: columns x, y, theta (m, m, rad)")->required();
       app.add_option("PATTERN", o->pattern, "CSV of the slots' poses: columns x, y, theta, one slot per bar")->required();
       app.add_option("--scene", o->scene, "scene giving the bar, the surface and the tip")->capture_default_str();
       add_set_option(app, o->sets);
       app.add_option("--tolerance", o->tolerance, "D,A: distance (m) and angle (rad) within which a bar is in its slot")
           ->capture_default_str();
       app.add_option("--objective", o->objective, "each bar's plan: pushes, travel, time or force")->capture_default_str();
       app.add_option("--max-pushes", o->max_pushes, "largest number of pushes per bar")
           ->check(count(1, 1000))
           ->capture_default_str();
       app.add_option("--gap", o->gap, "least distance kept between bars, and between a tip and another bar (m)")
           ->check(non_negative())
           ->capture_default_str();
       app.add_option("--out", o->out, "output directory (default <scene>.assembly)");
       app.add_option("--format", o->format, "figure format: png, svg or pdf")->capture_default_str();
       app.add_flag("--quiet", o->quiet, "no summary on standard error");
       return [o] { return assemble_cmd(*o); };
     }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
