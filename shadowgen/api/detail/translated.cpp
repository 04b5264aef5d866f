#include "detail/translated.h"

#include <string>

#include "clipper/clip.h"
#include "hsr/hidden_surface.h"
#include "shadowgen/api/errors.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::api::detail {

void rethrow_public() {
  try {
    throw;
  } catch (const shadowgen::InputError& e) {
    throw api::InputError(e.what(), e.file(), e.face_id(), e.problem());
  } catch (const shadowgen::GenerationError& e) {
    throw api::GenerationError(e.what(), e.file(), e.face_id(), e.light_id(), e.problem());
  } catch (const clipper::SnapRoundingError& e) {
    throw api::GenerationError(e.what(), "", "", "", e.what());
  } catch (const hsr::PolygonClipError& e) {
    throw api::GenerationError(e.what(), "", "", "", e.what());
  }
}

}  // namespace shadowgen::api::detail
