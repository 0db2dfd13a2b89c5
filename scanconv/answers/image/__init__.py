"""The answers of "Image representation": frame-buffer storage, quantization, sampling,
grey ramps, dithering and halftoning, frame buffers and colour."""
