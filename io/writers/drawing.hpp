// The drawing writers: SVG (svg_writer.hpp) and exact JSON (json_writer.hpp).
#pragma once

#include "io/writers/json_writer.hpp"
#include "io/writers/svg_writer.hpp"
