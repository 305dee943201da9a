#version 430 core
// One colour over the viewport (FlameFinisher: the empty pixels around a bounded finish). Drawn,
// not cleared: on a software rasteriser a clear of the finished image before the tone's draw made
// the finish half again as slow.

uniform vec4 uColour;
out vec4 fragColor;

void main() { fragColor = uColour; }
