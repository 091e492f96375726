#pragma once
// In-process Python members: a user's member class (docs/python.md, "Member classes") run inside the gdnav process
// through an embedded interpreter, as the component type `python_member` (run.members: {NAME: {python: {file: F,
// class: C}}}, framework/run_members.hpp). Only the program that hosts components links this (and libpython).
#include "framework/registry.hpp"

namespace gdnav::client::embed {

// Adds the component type `python_member`. `reg` must outlive the components it creates (the member checks its
// ports against the type it replaces).
void register_python_member(framework::ComponentRegistry& reg);

}  // namespace gdnav::client::embed
