// Profile planners: being written (see profiles.hpp).
