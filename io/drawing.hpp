// The drawing writers: SVG (svg_writer.hpp) and exact JSON (json_writer.hpp).
#pragma once

#include "io/json_writer.hpp"
#include "io/svg_writer.hpp"
