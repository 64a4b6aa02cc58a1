"""The library layer: program files on disk, their encodings, and the workspace's programs."""
