// A record whose run still matches but whose scene file changed (a comment, another variant, a
// tolerance): `golden check --update` stamps it with the file's new sha256 instead of recording it
// again, so the next check has no stale "changed since it was recorded" warning and the record's
// states, draw lists and frames stay the ones that were reviewed.
#pragma once

#include "render/golden/golden_record.h"
#include "render/golden/record_manifest.h"

namespace render::golden {

// `record`'s manifest.json rewritten in place (atomically) with `info`'s scene file, sha256, size and
// tolerances, its checkpoints, frames and renderer kept; throws std::runtime_error
void restampRecord(const GoldenRecord& record, const RecordInfo& info);

}  // namespace render::golden
