#pragma once

#if FASTSIMD_MAX_FEATURE_VALUE() >= FASTSIMD_FEATURE_VALUE( NEON )
#include "NEON.h"
#endif
