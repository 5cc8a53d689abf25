#include "elements/rows.h"

#include "elements/cam_row.h"

namespace linkage {

bool Row::sameNumbers(const Row& o) const {
  if (s[0] != o.s[0] || s[1] != o.s[1] || n != o.n || c[0] != o.c[0] || c[1] != o.c[1] ||
      c[2] != o.c[2] || value != o.value || driven != o.driven)
    return false;
  return cam == o.cam || (cam && o.cam && *cam == *o.cam);
}

}  // namespace linkage
