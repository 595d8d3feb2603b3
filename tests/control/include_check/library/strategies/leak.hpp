#pragma once
#include "strategies/inside.hpp"
#include "sim/scene.hpp"
#include "../../sim/scene.hpp"
#include <sim/scene.hpp>
#include <fragsim/control.h>
#include "inside.hpp"
#include <vector>
