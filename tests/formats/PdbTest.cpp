/* Pdb: the reader against the files its real writers made (tests/data/formats). */

#include "FormatTestData.h"
