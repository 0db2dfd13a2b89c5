"""Visible-surface detection (``scanconv 3d``): back faces, the z-buffer, Warnock's area
subdivision."""
