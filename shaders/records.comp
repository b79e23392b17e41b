// Exact first-hit ray casting of an SBRT into hit records (Pass::records):
// a record for each pixel of the band, which the host reads back and
// shades, or keeps on the GPU for the kernel normals' passes. The ray's
// walk is common/trace_pixel.glsl's.

layout(local_size_x = 8, local_size_y = 8) in;

// The end of the pixel's ray as its hit record
void finish(uint index, vec3 point, uint code, float t)
{
    hits[index] = PixelHit(point, code, vec4(veil, transmittance));
}

void main()
{
    trace_pixel();
}
