"""An agent that sends navigation goals to Nav2's NavigateToPose action server."""
