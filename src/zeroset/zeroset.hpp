// zeroset's public API in one include (docs/library.md): expressions and
// shapes, scenes (read or built), rendering to an Image, slices, the
// one-ray inspector, and image files. The other headers are internal: they
// are installed because these include them, and may change without notice.
#pragma once

#include "zeroset/expr/expr.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/expr/deform.hpp"
#include "zeroset/expr/vm_import.hpp"
#include "zeroset/io/image_reader.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/ray_probe.hpp"
#include "zeroset/render/ray_report.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/render/slice.hpp"
#include "zeroset/scene/expression_parser.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/scene/scene.hpp"
