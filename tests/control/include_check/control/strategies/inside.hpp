#pragma once
#include "fragsim/control.h"
