// Every feature of the main window (main_window.h), for code that reaches into several of them
// (the tests, the benchmarks).
#pragma once

#include "window/animation_feature.h"
#include "window/cam_feature.h"
#include "window/centres_feature.h"
#include "window/cycle_feature.h"
#include "window/design_feature.h"
#include "window/edit_feature.h"
#include "window/export_feature.h"
#include "window/file_feature.h"
#include "window/forces_feature.h"
#include "window/main_window.h"
#include "window/mechanisms_feature.h"
#include "window/plots_feature.h"
#include "window/properties_feature.h"
#include "window/sensitivity_feature.h"
#include "window/tools_feature.h"
#include "window/view3d_feature.h"
#include "window/view_feature.h"
