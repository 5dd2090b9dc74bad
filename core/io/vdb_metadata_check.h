// checkVdbMetadata(): walks an OpenVDB metadata map (MetaMap::readMeta's
// layout: a count, then name, type, size and value per entry) as the file
// and grid checks do, so that OpenVDB's reader cannot be made to allocate
// what an entry merely claims. Types OpenVDB reads at a fixed size must
// declare that size; a "__delayedload" entry (DelayedLoadMetadata, which
// real files carry and whose reader trusts its own counts) must hold its
// mask and compressed sizes, raw or as blosc chunks that unpack to them,
// within the entry. Throws Error starting with `where`.
#pragma once

#include <string>

#include "core/io/file_cursor.h"

namespace sandstorm {

void checkVdbMetadata(FileCursor& cursor, const std::string& where);

}  // namespace sandstorm
