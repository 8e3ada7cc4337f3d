-- args: --timeout 0.3
while true do coroutine.resume(coroutine.create(function() while true do end end)) end
