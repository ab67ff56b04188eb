#include "test_scenes.h"
