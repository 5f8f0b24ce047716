// The binding functions of each part of the module (module.cpp calls them in order).
#pragma once

#include <nanobind/nanobind.h>

namespace fosssim::py {

void bindScene(nanobind::module_& m);
void bindSimulator(nanobind::module_& m);
void bindPictures(nanobind::module_& m);
void bindTrajectories(nanobind::module_& m);

}  // namespace fosssim::py
