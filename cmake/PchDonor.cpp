// Compiled only so that its target makes the precompiled headers others reuse.
