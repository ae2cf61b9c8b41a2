#version 330 core
// Two-sided Blinn-Phong with a head light; optional per-vertex scalar shown through a colour map, or
// a material's base colour (factor times texture, KHR_texture_transform, alpha mask or blend).
in vec3 vViewPosition;
in vec3 vViewNormal;
in float vScalar;
in vec3 vColor;
in vec2 vTexCoord;

uniform int uColorMode;   // 0: surface colour, 1: scalar through the colour map, 2: vertex colour, 3: material
uniform vec3 uSurfaceColor;
uniform int uWireframe;   // 1 for the line pass
uniform vec4 uWireColor;
// Material (uColorMode 3): base colour factor in display values, texture on unit 1.
uniform vec4 uBaseColor;
uniform int uHasTexture;
uniform sampler2D uBaseTexture;
uniform mat3 uTexTransform;
uniform int uAlphaMode;   // 0 opaque, 1 mask, 2 blend
uniform float uAlphaCutoff;

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
    float alpha = 1.0;
    if (uColorMode == 3) {
        vec4 material = uBaseColor;
        if (uHasTexture == 1) material *= texture(uBaseTexture, (uTexTransform * vec3(vTexCoord, 1.0)).xy);
        if (uAlphaMode == 1 && material.a < uAlphaCutoff) discard;
        base = material.rgb;
        alpha = uAlphaMode == 2 ? material.a : 1.0;
    }
    float diffuse = max(dot(n, v), 0.0);
    vec3 h = normalize(v + normalize(vec3(0.3, 0.5, 1.0)));
    float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.25;
    float fill = max(dot(n, normalize(vec3(-0.6, 0.3, 0.5))), 0.0) * 0.25;
    vec3 color = base * (0.22 + 0.68 * diffuse + fill) + vec3(specular);
    fragColor = vec4(pow(color, vec3(1.0 / 1.1)), alpha);
}
