local pts = hoist.mirror { { 0.1, 0 }, { 0.3, 0.4 } }
