#version 330 core
// Live deformation: the rest position plus the weighted sum of morph targets (viseme deltas or
// deformation-field samples), fetched from a texture buffer, so a slider change costs one uniform
// upload instead of re-uploading the mesh.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aScalar;
layout(location = 3) in vec3 aColor;
layout(location = 4) in vec2 aTexCoord; // materials only (GpuSurface)
layout(location = 5) in int aSource;    // materials only: the mesh vertex this vertex draws

const int kMaxTargets = 128;

uniform mat4 uModelView;
uniform mat4 uProjection;
// Target t occupies texels [2*t*V, 2*t*V + V) for position deltas and the next V for normal deltas.
uniform samplerBuffer uTargets;
uniform int uTargetCount;
uniform int uVertexCount;
uniform float uTargetWeights[kMaxTargets];
// 1 while GpuSurface draws: its vertices split the mesh's at UV seams, aSource names the mesh vertex.
uniform int uUseSource;

out vec3 vViewPosition;
out vec3 vViewNormal;
out float vScalar;
out vec3 vColor;
out vec2 vTexCoord;

void main() {
    vec3 position = aPosition;
    vec3 normal = aNormal;
    int vertex = uUseSource == 1 ? aSource : gl_VertexID;
    for (int t = 0; t < uTargetCount; ++t) {
        float w = uTargetWeights[t];
        if (w == 0.0) continue;
        int base = 2 * t * uVertexCount + vertex;
        position += w * texelFetch(uTargets, base).xyz;
        normal += w * texelFetch(uTargets, base + uVertexCount).xyz;
    }
    vec4 viewPosition = uModelView * vec4(position, 1.0);
    vViewPosition = viewPosition.xyz;
    vViewNormal = mat3(uModelView) * normal;
    vScalar = aScalar;
    vColor = aColor;
    vTexCoord = aTexCoord;
    gl_Position = uProjection * viewPosition;
}
