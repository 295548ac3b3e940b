// The oracle's registry entry: `exact`, the reference visible set, with its
// knobs (culling/oracle/oracle_options.h).
#pragma once
#include "culling/api/family.h"
#include "culling/oracle/oracle_options.h"

namespace gridcull {

FamilyEntry oracleFamily();

}  // namespace gridcull
