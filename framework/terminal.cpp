// Progress bar (placeholder).
