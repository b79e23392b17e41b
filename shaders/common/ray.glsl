// The state of one ray (one invocation) of the ray casting shaders:
// where it starts, what the translucent strata it crossed let through.

// a plane's signed distance from the origin hi + lo along one axis
float from_origin(float plane, float hi, float lo)
{
    precise float distance = (plane - hi) - lo;
    return distance;
}

// light of the translucent strata crossed so far (premultiplied colour)
// and the share of what is behind that still reaches the camera
vec3 veil = vec3(0.0);
float transmittance = 1.0;
const float MIN_TRANSMITTANCE = 1.0 / 4096.0;

// the ray of this invocation (local frame) and the t of the camera's eye
vec3 ray_d = vec3(0.0);
float t_eye = 0.0;

#ifdef SBRT_SHADE
// Pixel `index` to the host, which traces it again (over the loop
// budget): what the GPU writes for it is the background kept before the
// trace, seen as it was then (no veil)
void send_back(uint index)
{
    flag_over_budget(index);
    veil = vec3(0.0);
    transmittance = 1.0;
}
#endif

// Beer-Lambert over `length` map units of a translucent material; true
// once (almost) nothing behind can be seen
bool absorb(vec4 material, float length)
{
    float keep = exp(-material.w * length);
    veil += transmittance * (1.0 - keep) * material.rgb;
    transmittance *= keep;
    return transmittance < MIN_TRANSMITTANCE;
}
