<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis version="3.22.16-Białowieża" minScale="100000000" hasScaleBasedVisibilityFlag="0" simplifyMaxScale="1" symbologyReferenceScale="-1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyDrawingTol="1" simplifyAlgorithm="0" simplifyDrawingHints="1" maxScale="0" simplifyLocal="1" labelsEnabled="1">
  <renderer-v2 type="RuleRenderer" referencescale="-1" symbollevels="0" forceraster="0" enableorderby="1">
    <rules key="{22dc7556-ac86-4cf2-b3c1-bec48f62d54a}">
      <rule symbol="0" label="AT mine indication" key="{08a32170-a57a-4a57-b7e6-43257bdf0b3b}" filter="&quot;class_cue&quot; = 'at_mine'"/>
      <rule symbol="1" label="AP mine indication" key="{22f1a81d-a3f9-4a22-bb5b-59b2e93167b6}" filter="&quot;class_cue&quot; = 'ap_mine'"/>
      <rule symbol="2" label="Other suspect" key="{ae9a5b10-d81d-4ba3-8412-c56e73979ddf}" filter="&quot;class_cue&quot; NOT IN ('at_mine', 'ap_mine', 'clutter') OR &quot;class_cue&quot; IS NULL"/>
      <rule checkstate="0" symbol="3" label="Clutter" key="{2d33a244-dc1e-46a9-9991-0d03a7a28c45}" filter="&quot;class_cue&quot; = 'clutter'"/>
    </rules>
    <symbols>
      <symbol type="marker" alpha="1" clip_to_extent="1" force_rhr="0" name="0">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" value="" name="name"/>
            <Option name="properties"/>
            <Option type="QString" value="collection" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" pass="0" class="SimpleMarker" locked="0">
          <Option type="Map">
            <Option type="QString" value="0" name="angle"/>
            <Option type="QString" value="square" name="cap_style"/>
            <Option type="QString" value="227,26,28,255" name="color"/>
            <Option type="QString" value="1" name="horizontal_anchor_point"/>
            <Option type="QString" value="bevel" name="joinstyle"/>
            <Option type="QString" value="triangle" name="name"/>
            <Option type="QString" value="0,0" name="offset"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="offset_map_unit_scale"/>
            <Option type="QString" value="MM" name="offset_unit"/>
            <Option type="QString" value="35,35,35,255" name="outline_color"/>
            <Option type="QString" value="solid" name="outline_style"/>
            <Option type="QString" value="0.3" name="outline_width"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale"/>
            <Option type="QString" value="MM" name="outline_width_unit"/>
            <Option type="QString" value="diameter" name="scale_method"/>
            <Option type="QString" value="5" name="size"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="size_map_unit_scale"/>
            <Option type="QString" value="MM" name="size_unit"/>
            <Option type="QString" value="1" name="vertical_anchor_point"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="5" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" value="" name="name"/>
              <Option name="properties"/>
              <Option type="QString" value="collection" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="1" clip_to_extent="1" force_rhr="0" name="1">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" value="" name="name"/>
            <Option name="properties"/>
            <Option type="QString" value="collection" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" pass="0" class="SimpleMarker" locked="0">
          <Option type="Map">
            <Option type="QString" value="0" name="angle"/>
            <Option type="QString" value="square" name="cap_style"/>
            <Option type="QString" value="227,26,28,255" name="color"/>
            <Option type="QString" value="1" name="horizontal_anchor_point"/>
            <Option type="QString" value="bevel" name="joinstyle"/>
            <Option type="QString" value="triangle" name="name"/>
            <Option type="QString" value="0,0" name="offset"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="offset_map_unit_scale"/>
            <Option type="QString" value="MM" name="offset_unit"/>
            <Option type="QString" value="35,35,35,255" name="outline_color"/>
            <Option type="QString" value="solid" name="outline_style"/>
            <Option type="QString" value="0.3" name="outline_width"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale"/>
            <Option type="QString" value="MM" name="outline_width_unit"/>
            <Option type="QString" value="diameter" name="scale_method"/>
            <Option type="QString" value="4" name="size"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="size_map_unit_scale"/>
            <Option type="QString" value="MM" name="size_unit"/>
            <Option type="QString" value="1" name="vertical_anchor_point"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" value="" name="name"/>
              <Option name="properties"/>
              <Option type="QString" value="collection" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="0.6" clip_to_extent="1" force_rhr="0" name="2">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" value="" name="name"/>
            <Option name="properties"/>
            <Option type="QString" value="collection" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" pass="0" class="SimpleMarker" locked="0">
          <Option type="Map">
            <Option type="QString" value="0" name="angle"/>
            <Option type="QString" value="square" name="cap_style"/>
            <Option type="QString" value="255,127,0,255" name="color"/>
            <Option type="QString" value="1" name="horizontal_anchor_point"/>
            <Option type="QString" value="bevel" name="joinstyle"/>
            <Option type="QString" value="circle" name="name"/>
            <Option type="QString" value="0,0" name="offset"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="offset_map_unit_scale"/>
            <Option type="QString" value="MM" name="offset_unit"/>
            <Option type="QString" value="90,90,90,255" name="outline_color"/>
            <Option type="QString" value="solid" name="outline_style"/>
            <Option type="QString" value="0.3" name="outline_width"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale"/>
            <Option type="QString" value="MM" name="outline_width_unit"/>
            <Option type="QString" value="diameter" name="scale_method"/>
            <Option type="QString" value="2.4" name="size"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="size_map_unit_scale"/>
            <Option type="QString" value="MM" name="size_unit"/>
            <Option type="QString" value="1" name="vertical_anchor_point"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="255,127,0,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2.4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" value="" name="name"/>
              <Option name="properties"/>
              <Option type="QString" value="collection" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="0.6" clip_to_extent="1" force_rhr="0" name="3">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" value="" name="name"/>
            <Option name="properties"/>
            <Option type="QString" value="collection" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" pass="0" class="SimpleMarker" locked="0">
          <Option type="Map">
            <Option type="QString" value="0" name="angle"/>
            <Option type="QString" value="square" name="cap_style"/>
            <Option type="QString" value="150,150,150,255" name="color"/>
            <Option type="QString" value="1" name="horizontal_anchor_point"/>
            <Option type="QString" value="bevel" name="joinstyle"/>
            <Option type="QString" value="circle" name="name"/>
            <Option type="QString" value="0,0" name="offset"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="offset_map_unit_scale"/>
            <Option type="QString" value="MM" name="offset_unit"/>
            <Option type="QString" value="90,90,90,255" name="outline_color"/>
            <Option type="QString" value="solid" name="outline_style"/>
            <Option type="QString" value="0.3" name="outline_width"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale"/>
            <Option type="QString" value="MM" name="outline_width_unit"/>
            <Option type="QString" value="diameter" name="scale_method"/>
            <Option type="QString" value="2" name="size"/>
            <Option type="QString" value="3x:0,0,0,0,0,0" name="size_map_unit_scale"/>
            <Option type="QString" value="MM" name="size_unit"/>
            <Option type="QString" value="1" name="vertical_anchor_point"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="150,150,150,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" value="" name="name"/>
              <Option name="properties"/>
              <Option type="QString" value="collection" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <orderby>
      <orderByClause asc="0" nullsFirst="1">coalesce(attribute('priority'), 1000000 * (CASE WHEN "class_cue" = 'at_mine' THEN 0 WHEN "class_cue" = 'ap_mine' THEN 1 WHEN "class_cue" = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs("contrast_day_k"), abs("contrast_night_k"))))</orderByClause>
    </orderby>
  </renderer-v2>
  <labeling type="rule-based">
    <rules key="{508f0c39-a6ac-4204-bcc3-58521689d155}">
      <rule description="Mine indications" key="{6f176da7-2487-48ee-84ce-4feb5c724209}" filter="&quot;class_cue&quot; IN ('at_mine', 'ap_mine')">
        <settings calloutType="simple">
          <text-style fontKerning="1" isExpression="0" fontItalic="0" fontFamily="DejaVu Sans" namedStyle="" legendString="Aa" allowHtml="0" multilineHeight="1" textColor="120,0,0,255" previewBkgrdColor="255,255,255,255" fontWordSpacing="0" fontLetterSpacing="0" fontStrikeout="0" capitalization="0" fontSizeUnit="Point" blendMode="0" textOrientation="horizontal" useSubstitutions="0" textOpacity="1" fontUnderline="0" fieldName="short_id" fontSizeMapUnitScale="3x:0,0,0,0,0,0" fontWeight="75" fontSize="9">
            <families/>
            <text-buffer bufferOpacity="1" bufferSizeMapUnitScale="3x:0,0,0,0,0,0" bufferColor="255,255,255,255" bufferSizeUnits="MM" bufferNoFill="1" bufferDraw="1" bufferJoinStyle="128" bufferBlendMode="0" bufferSize="0.80000000000000004"/>
            <text-mask maskSize="1.5" maskEnabled="0" maskOpacity="1" maskType="0" maskSizeUnits="MM" maskedSymbolLayers="" maskSizeMapUnitScale="3x:0,0,0,0,0,0" maskJoinStyle="128"/>
            <background shapeOpacity="1" shapeOffsetY="0" shapeType="0" shapeOffsetX="0" shapeBlendMode="0" shapeRadiiX="0" shapeBorderWidth="0" shapeBorderColor="128,128,128,255" shapeSizeX="0" shapeRadiiUnit="MM" shapeSizeMapUnitScale="3x:0,0,0,0,0,0" shapeSizeY="0" shapeSizeUnit="MM" shapeBorderWidthUnit="MM" shapeRotation="0" shapeSVGFile="" shapeJoinStyle="64" shapeRadiiY="0" shapeSizeType="0" shapeDraw="0" shapeOffsetMapUnitScale="3x:0,0,0,0,0,0" shapeRotationType="0" shapeOffsetUnit="MM" shapeRadiiMapUnitScale="3x:0,0,0,0,0,0" shapeFillColor="255,255,255,255" shapeBorderWidthMapUnitScale="3x:0,0,0,0,0,0">
              <symbol type="fill" alpha="1" clip_to_extent="1" force_rhr="0" name="fillSymbol">
                <data_defined_properties>
                  <Option type="Map">
                    <Option type="QString" value="" name="name"/>
                    <Option name="properties"/>
                    <Option type="QString" value="collection" name="type"/>
                  </Option>
                </data_defined_properties>
                <layer enabled="1" pass="0" class="SimpleFill" locked="0">
                  <Option type="Map">
                    <Option type="QString" value="3x:0,0,0,0,0,0" name="border_width_map_unit_scale"/>
                    <Option type="QString" value="255,255,255,255" name="color"/>
                    <Option type="QString" value="bevel" name="joinstyle"/>
                    <Option type="QString" value="0,0" name="offset"/>
                    <Option type="QString" value="3x:0,0,0,0,0,0" name="offset_map_unit_scale"/>
                    <Option type="QString" value="MM" name="offset_unit"/>
                    <Option type="QString" value="128,128,128,255" name="outline_color"/>
                    <Option type="QString" value="no" name="outline_style"/>
                    <Option type="QString" value="0" name="outline_width"/>
                    <Option type="QString" value="MM" name="outline_width_unit"/>
                    <Option type="QString" value="solid" name="style"/>
                  </Option>
                  <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
                  <prop v="255,255,255,255" k="color"/>
                  <prop v="bevel" k="joinstyle"/>
                  <prop v="0,0" k="offset"/>
                  <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
                  <prop v="MM" k="offset_unit"/>
                  <prop v="128,128,128,255" k="outline_color"/>
                  <prop v="no" k="outline_style"/>
                  <prop v="0" k="outline_width"/>
                  <prop v="MM" k="outline_width_unit"/>
                  <prop v="solid" k="style"/>
                  <data_defined_properties>
                    <Option type="Map">
                      <Option type="QString" value="" name="name"/>
                      <Option name="properties"/>
                      <Option type="QString" value="collection" name="type"/>
                    </Option>
                  </data_defined_properties>
                </layer>
              </symbol>
            </background>
            <shadow shadowOffsetAngle="135" shadowRadiusMapUnitScale="3x:0,0,0,0,0,0" shadowColor="0,0,0,255" shadowBlendMode="6" shadowOffsetDist="1" shadowOffsetUnit="MM" shadowOffsetGlobal="1" shadowRadiusUnit="MM" shadowScale="100" shadowRadius="1.5" shadowUnder="0" shadowDraw="0" shadowOffsetMapUnitScale="3x:0,0,0,0,0,0" shadowRadiusAlphaOnly="0" shadowOpacity="0.69999999999999996"/>
            <dd_properties>
              <Option type="Map">
                <Option type="QString" value="" name="name"/>
                <Option name="properties"/>
                <Option type="QString" value="collection" name="type"/>
              </Option>
            </dd_properties>
            <substitutions/>
          </text-style>
          <text-format wrapChar="" placeDirectionSymbol="0" reverseDirectionSymbol="0" autoWrapLength="0" multilineAlign="3" formatNumbers="0" useMaxLineLengthForAutoWrap="1" rightDirectionSymbol=">" leftDirectionSymbol="&lt;" decimals="3" addDirectionSymbol="0" plussign="0"/>
          <placement quadOffset="4" maxCurvedCharAngleOut="-25" priority="9" overrunDistanceMapUnitScale="3x:0,0,0,0,0,0" centroidInside="0" maxCurvedCharAngleIn="25" distMapUnitScale="3x:0,0,0,0,0,0" labelOffsetMapUnitScale="3x:0,0,0,0,0,0" geometryGenerator="" centroidWhole="0" preserveRotation="1" geometryGeneratorType="PointGeometry" yOffset="0" lineAnchorPercent="0.5" rotationAngle="0" fitInPolygonOnly="0" offsetType="0" rotationUnit="AngleDegrees" repeatDistance="0" polygonPlacementFlags="2" offsetUnits="MM" distUnits="MM" placement="6" geometryGeneratorEnabled="0" lineAnchorType="0" overrunDistance="0" xOffset="0" predefinedPositionOrder="TR,TL,BR,BL,R,L,TSR,BSR" layerType="UnknownGeometry" lineAnchorClipping="0" placementFlags="10" repeatDistanceUnits="MM" repeatDistanceMapUnitScale="3x:0,0,0,0,0,0" dist="1" overrunDistanceUnit="MM"/>
          <rendering scaleVisibility="0" drawLabels="1" limitNumLabels="0" fontMinPixelSize="0" fontMaxPixelSize="10000" scaleMax="0" labelPerPart="0" upsidedownLabels="0" scaleMin="0" obstacleType="1" minFeatureSize="0" obstacle="1" mergeLines="0" zIndex="0" displayAll="0" fontLimitPixelSize="0" maxNumLabels="2000" obstacleFactor="1" unplacedVisibility="0"/>
          <dd_properties>
            <Option type="Map">
              <Option type="QString" value="" name="name"/>
              <Option name="properties"/>
              <Option type="QString" value="collection" name="type"/>
            </Option>
          </dd_properties>
          <callout type="simple">
            <Option type="Map">
              <Option type="QString" value="pole_of_inaccessibility" name="anchorPoint"/>
              <Option type="int" value="0" name="blendMode"/>
              <Option type="Map" name="ddProperties">
                <Option type="QString" value="" name="name"/>
                <Option name="properties"/>
                <Option type="QString" value="collection" name="type"/>
              </Option>
              <Option type="bool" value="false" name="drawToAllParts"/>
              <Option type="QString" value="0" name="enabled"/>
              <Option type="QString" value="point_on_exterior" name="labelAnchorPoint"/>
              <Option type="QString" value="&lt;symbol type=&quot;line&quot; alpha=&quot;1&quot; clip_to_extent=&quot;1&quot; force_rhr=&quot;0&quot; name=&quot;symbol&quot;>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; value=&quot;&quot; name=&quot;name&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;collection&quot; name=&quot;type&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;layer enabled=&quot;1&quot; pass=&quot;0&quot; class=&quot;SimpleLine&quot; locked=&quot;0&quot;>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;align_dash_pattern&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;square&quot; name=&quot;capstyle&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;5;2&quot; name=&quot;customdash&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;customdash_map_unit_scale&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;customdash_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;dash_pattern_offset&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;dash_pattern_offset_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;draw_inside_polygon&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;bevel&quot; name=&quot;joinstyle&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;60,60,60,255&quot; name=&quot;line_color&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;solid&quot; name=&quot;line_style&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0.3&quot; name=&quot;line_width&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;line_width_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;offset&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;offset_map_unit_scale&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;offset_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;ring_filter&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;trim_distance_end&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;trim_distance_end_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;trim_distance_start&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;MM&quot; name=&quot;trim_distance_start_unit&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;0&quot; name=&quot;use_custom_dash&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;width_map_unit_scale&quot;/>&lt;/Option>&lt;prop v=&quot;0&quot; k=&quot;align_dash_pattern&quot;/>&lt;prop v=&quot;square&quot; k=&quot;capstyle&quot;/>&lt;prop v=&quot;5;2&quot; k=&quot;customdash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;customdash_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;customdash_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;dash_pattern_offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;dash_pattern_offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;draw_inside_polygon&quot;/>&lt;prop v=&quot;bevel&quot; k=&quot;joinstyle&quot;/>&lt;prop v=&quot;60,60,60,255&quot; k=&quot;line_color&quot;/>&lt;prop v=&quot;solid&quot; k=&quot;line_style&quot;/>&lt;prop v=&quot;0.3&quot; k=&quot;line_width&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;line_width_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;ring_filter&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_end&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_end_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_start&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_start_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;prop v=&quot;0&quot; k=&quot;use_custom_dash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;width_map_unit_scale&quot;/>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; value=&quot;&quot; name=&quot;name&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option type=&quot;QString&quot; value=&quot;collection&quot; name=&quot;type&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;/layer>&lt;/symbol>" name="lineSymbol"/>
              <Option type="double" value="0" name="minLength"/>
              <Option type="QString" value="3x:0,0,0,0,0,0" name="minLengthMapUnitScale"/>
              <Option type="QString" value="MM" name="minLengthUnit"/>
              <Option type="double" value="0" name="offsetFromAnchor"/>
              <Option type="QString" value="3x:0,0,0,0,0,0" name="offsetFromAnchorMapUnitScale"/>
              <Option type="QString" value="MM" name="offsetFromAnchorUnit"/>
              <Option type="double" value="0" name="offsetFromLabel"/>
              <Option type="QString" value="3x:0,0,0,0,0,0" name="offsetFromLabelMapUnitScale"/>
              <Option type="QString" value="MM" name="offsetFromLabelUnit"/>
            </Option>
          </callout>
        </settings>
      </rule>
    </rules>
  </labeling>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field configurationFlags="None" name="fid">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="anomaly_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="x">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="y">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lat">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="7" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lon">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="7" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="area_m2">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="3" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diameter_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="circularity">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="3" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_sigma_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="3" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_sigma_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="status">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="polarity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="class_cue">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="n_scans">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_day_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_night_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" value="true" name="AllowNull"/>
            <Option type="double" value="1e+09" name="Max"/>
            <Option type="double" value="-1e+09" name="Min"/>
            <Option type="int" value="2" name="Precision"/>
            <Option type="int" value="1" name="Step"/>
            <Option type="QString" value="SpinBox" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="fix_quality">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="figure">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_series">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="short_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="likelihood">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence_pct">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" value="false" name="IsMultiline"/>
            <Option type="bool" value="false" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="fid" index="0" name=""/>
    <alias field="anomaly_id" index="1" name="Suspect id"/>
    <alias field="x" index="2" name="Easting (m, survey UTM)"/>
    <alias field="y" index="3" name="Northing (m, survey UTM)"/>
    <alias field="lat" index="4" name="Latitude (°, WGS84)"/>
    <alias field="lon" index="5" name="Longitude (°, WGS84)"/>
    <alias field="area_m2" index="6" name="Area (m²)"/>
    <alias field="diameter_m" index="7" name="Diameter (m)"/>
    <alias field="circularity" index="8" name="Circularity (0-1)"/>
    <alias field="depth_m" index="9" name="Burial depth (m)"/>
    <alias field="depth_sigma_m" index="10" name="Depth uncertainty, 1σ (m)"/>
    <alias field="diffusivity_m2s" index="11" name="Thermal diffusivity (m²/s)"/>
    <alias field="diffusivity_sigma_m2s" index="12" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias field="status" index="13" name="Characterisation status"/>
    <alias field="polarity" index="14" name="Polarity"/>
    <alias field="class_cue" index="15" name="Class cue"/>
    <alias field="confidence" index="16" name="Class cue confidence (0-1)"/>
    <alias field="n_scans" index="17" name="Scans seen"/>
    <alias field="contrast_day_k" index="18" name="Day contrast (K)"/>
    <alias field="contrast_night_k" index="19" name="Night contrast (K)"/>
    <alias field="fix_quality" index="20" name="GNSS fix quality"/>
    <alias field="figure" index="21" name="Contrast curve"/>
    <alias field="contrast_series" index="22" name="Contrast series (JSON)"/>
    <alias field="short_id" index="23" name="Short id"/>
    <alias field="depth" index="24" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="25" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="26" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="27" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default expression="" field="fid" applyOnUpdate="0"/>
    <default expression="" field="anomaly_id" applyOnUpdate="0"/>
    <default expression="" field="x" applyOnUpdate="0"/>
    <default expression="" field="y" applyOnUpdate="0"/>
    <default expression="" field="lat" applyOnUpdate="0"/>
    <default expression="" field="lon" applyOnUpdate="0"/>
    <default expression="" field="area_m2" applyOnUpdate="0"/>
    <default expression="" field="diameter_m" applyOnUpdate="0"/>
    <default expression="" field="circularity" applyOnUpdate="0"/>
    <default expression="" field="depth_m" applyOnUpdate="0"/>
    <default expression="" field="depth_sigma_m" applyOnUpdate="0"/>
    <default expression="" field="diffusivity_m2s" applyOnUpdate="0"/>
    <default expression="" field="diffusivity_sigma_m2s" applyOnUpdate="0"/>
    <default expression="" field="status" applyOnUpdate="0"/>
    <default expression="" field="polarity" applyOnUpdate="0"/>
    <default expression="" field="class_cue" applyOnUpdate="0"/>
    <default expression="" field="confidence" applyOnUpdate="0"/>
    <default expression="" field="n_scans" applyOnUpdate="0"/>
    <default expression="" field="contrast_day_k" applyOnUpdate="0"/>
    <default expression="" field="contrast_night_k" applyOnUpdate="0"/>
    <default expression="" field="fix_quality" applyOnUpdate="0"/>
    <default expression="" field="figure" applyOnUpdate="0"/>
    <default expression="" field="contrast_series" applyOnUpdate="0"/>
    <default expression="" field="short_id" applyOnUpdate="0"/>
    <default expression="" field="depth" applyOnUpdate="0"/>
    <default expression="" field="diffusivity" applyOnUpdate="0"/>
    <default expression="" field="likelihood" applyOnUpdate="0"/>
    <default expression="" field="cue_confidence_pct" applyOnUpdate="0"/>
  </defaults>
  <constraints>
    <constraint field="fid" constraints="3" unique_strength="1" notnull_strength="1" exp_strength="0"/>
    <constraint field="anomaly_id" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="x" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="y" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="lat" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="lon" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="area_m2" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="diameter_m" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="circularity" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="depth_m" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="depth_sigma_m" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="diffusivity_m2s" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="diffusivity_sigma_m2s" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="status" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="polarity" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="class_cue" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="confidence" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="n_scans" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="contrast_day_k" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="contrast_night_k" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="fix_quality" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="figure" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="contrast_series" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="short_id" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="depth" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="diffusivity" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="likelihood" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
    <constraint field="cue_confidence_pct" constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint desc="" field="fid" exp=""/>
    <constraint desc="" field="anomaly_id" exp=""/>
    <constraint desc="" field="x" exp=""/>
    <constraint desc="" field="y" exp=""/>
    <constraint desc="" field="lat" exp=""/>
    <constraint desc="" field="lon" exp=""/>
    <constraint desc="" field="area_m2" exp=""/>
    <constraint desc="" field="diameter_m" exp=""/>
    <constraint desc="" field="circularity" exp=""/>
    <constraint desc="" field="depth_m" exp=""/>
    <constraint desc="" field="depth_sigma_m" exp=""/>
    <constraint desc="" field="diffusivity_m2s" exp=""/>
    <constraint desc="" field="diffusivity_sigma_m2s" exp=""/>
    <constraint desc="" field="status" exp=""/>
    <constraint desc="" field="polarity" exp=""/>
    <constraint desc="" field="class_cue" exp=""/>
    <constraint desc="" field="confidence" exp=""/>
    <constraint desc="" field="n_scans" exp=""/>
    <constraint desc="" field="contrast_day_k" exp=""/>
    <constraint desc="" field="contrast_night_k" exp=""/>
    <constraint desc="" field="fix_quality" exp=""/>
    <constraint desc="" field="figure" exp=""/>
    <constraint desc="" field="contrast_series" exp=""/>
    <constraint desc="" field="short_id" exp=""/>
    <constraint desc="" field="depth" exp=""/>
    <constraint desc="" field="diffusivity" exp=""/>
    <constraint desc="" field="likelihood" exp=""/>
    <constraint desc="" field="cue_confidence_pct" exp=""/>
  </constraintExpressions>
  <expressionfields>
    <field expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" type="10" comment="" length="0" precision="0" typeName="" subType="0" name="short_id"/>
    <field expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" type="10" comment="" length="0" precision="0" typeName="" subType="0" name="depth"/>
    <field expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" type="10" comment="" length="0" precision="0" typeName="" subType="0" name="diffusivity"/>
    <field expression="CASE WHEN attribute('p_mine') IS NULL THEN NULL ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" type="10" comment="" length="0" precision="0" typeName="" subType="0" name="likelihood"/>
    <field expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" type="10" comment="" length="0" precision="0" typeName="" subType="0" name="cue_confidence_pct"/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" sortOrder="0">
    <columns>
      <column type="field" width="-1" hidden="0" name="fid"/>
      <column type="field" width="-1" hidden="0" name="anomaly_id"/>
      <column type="field" width="-1" hidden="0" name="x"/>
      <column type="field" width="-1" hidden="0" name="y"/>
      <column type="field" width="-1" hidden="0" name="lat"/>
      <column type="field" width="-1" hidden="0" name="lon"/>
      <column type="field" width="-1" hidden="0" name="area_m2"/>
      <column type="field" width="-1" hidden="0" name="diameter_m"/>
      <column type="field" width="-1" hidden="0" name="circularity"/>
      <column type="field" width="-1" hidden="0" name="depth_m"/>
      <column type="field" width="-1" hidden="0" name="depth_sigma_m"/>
      <column type="field" width="-1" hidden="0" name="diffusivity_m2s"/>
      <column type="field" width="-1" hidden="0" name="diffusivity_sigma_m2s"/>
      <column type="field" width="-1" hidden="0" name="status"/>
      <column type="field" width="-1" hidden="0" name="polarity"/>
      <column type="field" width="-1" hidden="0" name="class_cue"/>
      <column type="field" width="-1" hidden="0" name="confidence"/>
      <column type="field" width="-1" hidden="0" name="n_scans"/>
      <column type="field" width="-1" hidden="0" name="contrast_day_k"/>
      <column type="field" width="-1" hidden="0" name="contrast_night_k"/>
      <column type="field" width="-1" hidden="0" name="fix_quality"/>
      <column type="field" width="-1" hidden="0" name="figure"/>
      <column type="field" width="-1" hidden="0" name="contrast_series"/>
      <column type="field" width="-1" hidden="0" name="short_id"/>
      <column type="field" width="-1" hidden="0" name="depth"/>
      <column type="field" width="-1" hidden="0" name="diffusivity"/>
      <column type="field" width="-1" hidden="0" name="likelihood"/>
      <column type="field" width="-1" hidden="0" name="cue_confidence_pct"/>
      <column type="actions" width="-1" hidden="1"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Suspect">
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Identification">
        <attributeEditorField index="23" showLabel="1" name="short_id"/>
        <attributeEditorField index="1" showLabel="1" name="anomaly_id"/>
        <attributeEditorField index="15" showLabel="1" name="class_cue"/>
        <attributeEditorField index="26" showLabel="1" name="likelihood"/>
        <attributeEditorField index="27" showLabel="1" name="cue_confidence_pct"/>
        <attributeEditorField index="13" showLabel="1" name="status"/>
        <attributeEditorField index="14" showLabel="1" name="polarity"/>
      </attributeEditorContainer>
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Burial depth and soil">
        <attributeEditorField index="24" showLabel="1" name="depth"/>
        <attributeEditorField index="25" showLabel="1" name="diffusivity"/>
      </attributeEditorContainer>
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Thermal contrast">
        <attributeEditorField index="18" showLabel="1" name="contrast_day_k"/>
        <attributeEditorField index="19" showLabel="1" name="contrast_night_k"/>
        <attributeEditorField index="17" showLabel="1" name="n_scans"/>
      </attributeEditorContainer>
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Shape">
        <attributeEditorField index="7" showLabel="1" name="diameter_m"/>
        <attributeEditorField index="6" showLabel="1" name="area_m2"/>
        <attributeEditorField index="8" showLabel="1" name="circularity"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Contrast curve">
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Contrast curve">
        <attributeEditorField index="21" showLabel="1" name="figure"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Position">
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Position">
        <attributeEditorField index="2" showLabel="1" name="x"/>
        <attributeEditorField index="3" showLabel="1" name="y"/>
        <attributeEditorField index="4" showLabel="1" name="lat"/>
        <attributeEditorField index="5" showLabel="1" name="lon"/>
        <attributeEditorField index="20" showLabel="1" name="fix_quality"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Stored values">
      <attributeEditorContainer visibilityExpression="" columnCount="1" groupBox="1" showLabel="1" visibilityExpressionEnabled="0" name="Stored values">
        <attributeEditorField index="9" showLabel="1" name="depth_m"/>
        <attributeEditorField index="10" showLabel="1" name="depth_sigma_m"/>
        <attributeEditorField index="11" showLabel="1" name="diffusivity_m2s"/>
        <attributeEditorField index="12" showLabel="1" name="diffusivity_sigma_m2s"/>
        <attributeEditorField index="16" showLabel="1" name="confidence"/>
        <attributeEditorField index="22" showLabel="1" name="contrast_series"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>0</layerGeometryType>
</qgis>
