// nanopush.Scene: scene files, presets (resolved in Python), Scene.set and the key table.
#include "common.hpp"

#include <filesystem>
#include <string>

#include <pybind11/stl/filesystem.h>

#include "nanopush/scenes/presets.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/scene_keys.hpp"

namespace nanopush::python {

namespace {

/// A Python value for scene key `key`: bool, integer, real, or text read as the key's type
/// (the command line's KEY=VALUE: "coulomb", "0.1").
SceneValue to_scene_value(const std::string& key, const py::handle& obj) {
  // A NumPy scalar or 0-d array is its Python value; a larger array is refused (InputError).
  const py::object v = plain_value(obj, key);
  if (PyBool_Check(v.ptr())) return SceneValue(v.ptr() == Py_True);
  if (py::isinstance<py::str>(v)) return SceneValue::from_text(key, v.cast<std::string>());
  if (PyLong_Check(v.ptr())) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (i == -1 && PyErr_Occurred()) throw py::error_already_set();
    if (overflow != 0)
      throw InputError(key, py::str(v).cast<std::string>(),
                       "an integer outside [-9223372036854775808, 9223372036854775807]: give a value in the key's range "
                       "(nanopush.scene_keys())");
    return SceneValue(static_cast<long>(i));
  }
  if (PyFloat_Check(v.ptr())) return SceneValue(PyFloat_AsDouble(v.ptr()));
  // Another number type (fractions.Fraction, decimal.Decimal, ...): as a real number.
  if (PyNumber_Check(v.ptr()) && !PyIndex_Check(v.ptr()) && Py_TYPE(v.ptr())->tp_as_number &&
      Py_TYPE(v.ptr())->tp_as_number->nb_float)
    return SceneValue(arg_double(v, key));
  if (PyIndex_Check(v.ptr())) {  // an integer-like type that is not int
    const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
    if (!i) {
      PyErr_Clear();
      throw InputError(key, py::repr(v).cast<std::string>(), "must be a number, an integer, a flag or text");
    }
    return to_scene_value(key, i);
  }
  throw InputError(key, py::repr(v).cast<std::string>(), "must be a number, an integer, a flag or text");
}

std::vector<SceneSetting> to_settings(const py::dict& d) {
  std::vector<SceneSetting> out;
  for (auto item : d) {
    if (!py::isinstance<py::str>(item.first))
      throw InputError("scene key", py::repr(item.first).cast<std::string>(), "must be a dotted key such as surface.mu");
    const auto key = item.first.cast<std::string>();
    out.emplace_back(key, to_scene_value(key, item.second));
  }
  return out;
}

py::dict push_info(const Scene& s) {
  py::dict d;
  d["force"] = s.push.force;
  d["direction"] = s.push.beta;
  d["point"] = py::make_tuple(s.push.pbx, s.push.pby);
  d["xn"] = s.push.pbx;
  d["yn"] = -s.push.pby;
  return d;
}

py::dict info(const Scene& s) {
  py::dict d;
  d["name"] = s.name;
  d["description"] = s.description;
  d["source"] = s.source.string();
  d["model"] = s.model;
  d["shape"] = s.shape;
  d["length"] = s.length;
  d["width"] = s.width;
  d["height"] = s.height;
  d["a"] = s.geometry.a;
  d["b"] = s.geometry.b;
  d["density"] = s.density;
  d["mass"] = s.mass;
  d["inertia"] = s.inertia;
  d["push"] = push_info(s);
  py::dict init;
  const char* names[] = {"x", "y", "theta", "vx", "vy", "omega"};
  for (int i = 0; i < kStateSize; ++i) init[names[i]] = s.initial[static_cast<std::size_t>(i)];
  d["initial"] = init;
  py::dict surf;
  surf["kind"] = to_string(s.surface.kind);
  surf["law"] = to_string(s.surface.law);
  surf["mu"] = s.surface.mu;
  surf["f_vdw"] = s.surface.f_vdw;
  surf["g"] = s.surface.g;
  surf["normal_load"] = s.rough() ? s.normal_load() : 0.0;
  d["surface"] = surf;
  py::dict sol;
  sol["t_end"] = s.solver.t_end;
  sol["samples"] = s.solver.samples;
  sol["rtol"] = s.solver.rtol;
  sol["atol"] = s.solver.atol;
  sol["engine"] = to_string(s.solver.engine);
  sol["method"] = to_string(s.solver.method);
  sol["precision"] = to_string(s.solver.precision);
  sol["h0"] = s.solver.h0;
  sol["hmax"] = s.solver.hmax;
  sol["max_steps"] = s.solver.max_steps;
  d["solver"] = sol;
  d["load_report"] = s.load_report;
  return d;
}

}  // namespace

void register_scenes(py::module_& m) {
  // The preset rule of the command line (scenes/presets.hpp); the directory is Python's.
  m.def(
      "_find_preset",
      [](const std::filesystem::path& dir, const std::string& name) -> py::object {
        const auto found = find_preset(dir, name);
        return found ? py::cast(found->string()) : py::none();
      },
      py::arg("dir"), py::arg("name"), "The file of a preset name under dir, or None (nanopush.Scene.preset).");
  m.def(
      "_list_presets",
      [](const std::filesystem::path& dir) {
        py::list out;
        for (const PresetEntry& p : list_presets(dir))
          out.append(py::make_tuple(p.name, p.short_name, p.description, p.path.string()));
        return out;
      },
      py::arg("dir"), "(name, short name, description, path) of every preset under dir, sorted by name.");
  py::class_<Scene>(m, "Scene", R"doc(A scene: the object, the push, the initial state, the surface and the solver
settings (docs/scenes.md; every number SI).

Build one with Scene.preset("fig3_6a"), Scene.from_file(path) or Scene.from_toml(text);
change it with scene.set("surface.mu", 0.1) (validated as the file is: a bad key or value
raises nanopush.InputError and leaves the scene unchanged). Scenes are values: copy.copy(scene)
or scene.copy() gives an independent one.)doc")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path) {
            // The library names the file SCENE (the command line's argument): here it is path.
            return bindings::with_argument_names({{"SCENE", "path"}}, [&] { return load_scene(path); });
          },
          py::arg("path"),
          "Read a scene file (TOML, at most 1 MiB). Raises nanopush.InputError naming the key, value and "
          "allowed range.")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::string& name) {
            if (text.size() > kMaxSceneBytes)
              throw InputError("scene text", std::to_string(text.size()) + " bytes",
                               "must be at most " + std::to_string(kMaxSceneBytes) + " bytes");
            return parse_scene(text, name);
          },
          py::arg("text"), py::arg("source_name") = "<string>",
          "A scene from TOML text (the file format). `source_name` names it in messages.")
      .def(
          "set", [](Scene& s, const std::string& key, const py::handle& value) { s.set(key, to_scene_value(key, value)); },
          py::arg("key"), py::arg("value"),
          "Set one scene key (dotted, e.g. 'surface.mu', 'push.yn' [m]) to a number, an integer, a flag, or text "
          "read as the key's type ('coulomb', '0.1'). Validated as the file is; on error the scene is unchanged.")
      .def(
          "set", [](Scene& s, const py::dict& settings) { s.set(to_settings(settings)); }, py::arg("settings"),
          "Set several keys at once, validated together: scene.set({'surface.kind': 'rough', 'surface.mu': 0.1}).")
      .def("unset", &Scene::unset, py::arg("key"), "Remove a key (back to its default); the scene must stay valid.")
      .def("to_toml", &Scene::to_toml, "The scene's document, with every set() applied (TOML text).")
      .def("info", &info,
           "What was read, as a dict (SI): name, description, source, model, geometry (length, width, height, "
           "a, b [m], density [kg/m^3], mass [kg], inertia [kg m^2]), push (force [N], direction [rad], "
           "point (x', y') [m] in body axes), initial state, surface and solver settings.")
      .def(
          "output_times",
          [](const Scene& s) {
            const auto t = s.output_times();
            return py::array_t<double>(static_cast<py::ssize_t>(t.size()), t.data());
          },
          "Output times [s]: solver.samples values evenly spaced over [0, solver.t_end].")
      .def_property_readonly("name", [](const Scene& s) { return s.name; }, "The scene's name.")
      .def_property_readonly("description", [](const Scene& s) { return s.description; })
      .def_property_readonly("rough", &Scene::rough, "True for a rough surface (surface.kind = 'rough').")
      .def("copy", [](const Scene& s) { return Scene(s); }, "An independent copy.")
      .def("__copy__", [](const Scene& s) { return Scene(s); })
      .def("__deepcopy__", [](const Scene& s, py::dict) { return Scene(s); }, py::arg("memo"))
      .def("__repr__", [](const Scene& s) {
        return "<nanopush.Scene '" + s.name + "' (" + s.model + ", t_end " + fmt(s.solver.t_end) + " s, " +
               std::to_string(s.solver.samples) + " samples)>";
      });

  m.def(
      "scene_keys",
      [] {
        py::list out;
        for (const auto& k : nanopush::scene_keys()) {
          py::dict d;
          d["key"] = std::string(k.key);
          d["type"] = std::string(key_type_name(k.type));
          d["unit"] = std::string(k.unit);
          d["default"] = std::string(k.default_text);
          d["allowed"] = std::string(k.range);
          d["surface"] = std::string(k.kinds);
          d["description"] = std::string(k.description);
          out.append(d);
        }
        return out;
      },
      "Every scene key as a dict (key, type, unit, default, allowed, surface, description): the table of "
      "docs/scenes.md and `nanopush scene-keys`.");
}

}  // namespace nanopush::python
