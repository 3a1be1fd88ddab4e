"""Battery and temperature health monitors for a robot."""
