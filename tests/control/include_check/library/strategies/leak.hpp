#pragma once
#include <fragsim/control.h>
#include <sim/scene.hpp>
#include <vector>
#include "../../sim/scene.hpp"
#include "inside.hpp"
#include "sim/scene.hpp"
#include "strategies/inside.hpp"
