#version 330 core
// Two-sided Blinn-Phong with a head light; optional per-vertex scalar shown through a colour map.
in vec3 vViewPosition;
in vec3 vViewNormal;
in float vScalar;
in vec3 vColor;

uniform int uColorMode;   // 0: surface colour, 1: scalar through the colour map, 2: vertex colour
uniform vec3 uSurfaceColor;
uniform int uWireframe;   // 1 for the line pass
uniform vec4 uWireColor;

out vec4 fragColor;

// Perceptually ordered blue -> teal -> yellow -> red ramp (a compact "turbo"-like map).
vec3 colorMap(float t) {
    t = clamp(t, 0.0, 1.0);
    const vec3 c0 = vec3(0.18, 0.24, 0.52);
    const vec3 c1 = vec3(0.15, 0.52, 0.92);
    const vec3 c2 = vec3(0.10, 0.85, 0.60);
    const vec3 c3 = vec3(0.95, 0.85, 0.20);
    const vec3 c4 = vec3(0.80, 0.12, 0.05);
    if (t < 0.25) return mix(c0, c1, t / 0.25);
    if (t < 0.5) return mix(c1, c2, (t - 0.25) / 0.25);
    if (t < 0.75) return mix(c2, c3, (t - 0.5) / 0.25);
    return mix(c3, c4, (t - 0.75) / 0.25);
}

void main() {
    if (uWireframe == 1) {
        fragColor = uWireColor;
        return;
    }
    vec3 n = normalize(vViewNormal);
    vec3 v = normalize(-vViewPosition);
    if (dot(n, v) < 0.0) n = -n;
    vec3 base = uColorMode == 1 ? colorMap(vScalar) : (uColorMode == 2 ? vColor : uSurfaceColor);
    float diffuse = max(dot(n, v), 0.0);
    vec3 h = normalize(v + normalize(vec3(0.3, 0.5, 1.0)));
    float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.25;
    float fill = max(dot(n, normalize(vec3(-0.6, 0.3, 0.5))), 0.0) * 0.25;
    vec3 color = base * (0.22 + 0.68 * diffuse + fill) + vec3(specular);
    fragColor = vec4(pow(color, vec3(1.0 / 1.1)), 1.0);
}
