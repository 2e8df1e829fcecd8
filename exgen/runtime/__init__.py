"""How exgen runs: files read safely (text and YAML), output folders replaced only when whole, worker
processes that end with their parent, interrupts, a faster allocator for typesetting, progress."""
