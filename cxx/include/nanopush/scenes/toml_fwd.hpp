// toml++'s document type, declared without toml++ (3.x: toml::v3::table). The installed headers
// name it (Scene::document, scene_from_document, parse_environment) but do not include toml++:
// nanopush_scenes compiles toml++'s code once (cxx/scenes/toml_impl.cpp), so neither a
// consumer nor the command line needs toml++ at link time (docs/performance.md, "Process
// start"). Code that reads or builds a document includes <toml++/toml.h> itself; a toml++ of
// another major version makes `toml::table` ambiguous there, a compile error, not a silent
// mismatch.
#pragma once

namespace toml {
inline namespace v3 {
class table;
}  // namespace v3
}  // namespace toml
