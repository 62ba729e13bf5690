#pragma once

#if FASTSIMD_MAX_FEATURE_VALUE() >= FASTSIMD_FEATURE_VALUE( SSE )
#include "SSE.h"
#endif
