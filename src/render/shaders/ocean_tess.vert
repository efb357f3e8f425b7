#version 450
// The tessellated mesh's vertex stage (docs/rendering.md R.40–R.42): one control point per base
// quad, carrying the quad's grid cell (i, j) from the per-frame list of visible cells; the
// tessellation control stage (ocean.tesc) sets its levels, the evaluation stage (ocean.tese)
// places and displaces the generated vertices.

layout(location = 0) in uint a_cell;  // i | j << 16, the quad's column and row in the base grid

layout(location = 0) out uvec2 cell;

void main() {
  cell = uvec2(a_cell & 0xffffu, a_cell >> 16u);
}
